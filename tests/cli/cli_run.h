// What every whole-program test shares: running the ssaolab binary and judging its failure.
#pragma once
#include "test_util.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace ssaotest {

struct CliRun {
    int exitCode = -1;
    bool signaled = false;
    std::string out, err;
};

// Runs `ssaolab ARGS` (after `env`, e.g. "VAR=1"), stdin from /dev/null, capturing both streams.
inline CliRun ssaolab(const std::string& args, const std::string& env = "") {
    std::filesystem::create_directories(SSAOLAB_TEST_TMP);
    // Reference traces are cached inside the build tree, not in the user's ~/.cache.
    ::setenv("SSAOLAB_CACHE_DIR", (std::string(SSAOLAB_TEST_TMP) + "/cache").c_str(), 0);
    const std::string base = std::string(SSAOLAB_TEST_TMP) + "/cli_" + std::to_string(::getpid());
    const std::string cmd = env + (env.empty() ? "" : " ") + std::string("'") + SSAOLAB_BINARY + "' " + args + " >" +
                            base + ".out 2>" + base + ".err </dev/null";
    int status = std::system(cmd.c_str());
    CliRun r;
    r.signaled = WIFSIGNALED(status);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(base + ".out");
    r.err = slurp(base + ".err");
    return r;
}

// Runs the shell command `cmd` on a virtual display (xvfb-run -a) and returns the command's own
// exit status (-1: it never ran). xvfb-run's own failures - a display number taken by a test
// starting at the same moment, "problem while cleaning up temporary directory" (exit 5) - are
// not the command's: the status is the command's, written by the shell xvfb-run starts, and a
// server that never came up is tried again.
inline int underXvfb(const std::string& cmd, const std::string& tag) {
    const std::string status = std::string(SSAOLAB_TEST_TMP) + "/xvfb_status_" + tag + "_" + std::to_string(::getpid());
    for (int attempt = 0; attempt < 3; ++attempt) {
        std::filesystem::remove(status);
        std::string quoted; // cmd inside single quotes for sh -c
        for (char c : cmd)
            quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        const std::string line = "xvfb-run -a -s '-screen 0 1280x800x24' sh -c '" + quoted + "; echo $? > " + status +
                                 "' </dev/null >/dev/null 2>&1";
        std::system(line.c_str());
        const std::string s = slurp(status);
        if (!s.empty()) return std::atoi(s.c_str());
    }
    return -1;
}

inline std::string outDir(const std::string& name) {
    return std::string(SSAOLAB_TEST_TMP) + "/out_" + name;
}

// One clear line naming the problem, exit code 1 (not a crash, not a hang).
inline void expectCleanFailure(const CliRun& r, const std::string& needle) {
    EXPECT_FALSE(r.signaled) << r.err;
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "expected one line, got:\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.err;
}

} // namespace ssaotest
