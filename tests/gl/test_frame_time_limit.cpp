// The per-frame time limit of headless runs (gl/frame_watchdog.h): a user technique whose shader
// never ends stops the process with one error line soon after the limit, instead of hanging it;
// a frame that ends renders as without the limit. The hanging frame runs in a child process
// (tests/gl/hang_child.cpp) with its own EGL context: the stuck context cannot be torn down.
#include "gl/readback.h"
#include "scene/load/load_scene.h"
#include "gl_fixture.h"

#include "scene/scene.h"
#include "techniques/technique.h"
#include "techniques/user/user_pass.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

using namespace ssao;
using namespace ssaotest;

namespace {
using Clock = std::chrono::steady_clock;
class FrameTimeLimit : public GlTest {};

constexpr const char* kMarker = "rendering the endless frame";

struct Child {
    int exitCode = -1;                       // -1: killed or signalled
    bool killed = false;                     // still running `killAfter` after the marker
    std::optional<double> markerToExit;      // seconds from the marker line to the exit
    std::string out, err;
};

// Runs tests/gl/hang_child.cpp with the limit, killing it `killAfter` seconds after it
// prints the marker (or 120 s after the start when it never does).
Child runChild(double limit, double killAfter) {
    int outPipe[2], errPipe[2];
    EXPECT_EQ(pipe(outPipe), 0);
    EXPECT_EQ(pipe(errPipe), 0);
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(outPipe[1], 1);
        dup2(errPipe[1], 2);
        close(outPipe[0]), close(errPipe[0]), close(outPipe[1]), close(errPipe[1]);
        const std::string arg = std::to_string(limit);
        execl(SSAOLAB_HANG_CHILD, "hang_child", arg.c_str(), (char*)nullptr);
        _exit(127);
    }
    close(outPipe[1]), close(errPipe[1]);
    Child c;
    const auto start = Clock::now();
    std::optional<Clock::time_point> marker;
    pollfd fds[2] = {{outPipe[0], POLLIN, 0}, {errPipe[0], POLLIN, 0}};
    int open = 2, status = 0;
    bool exited = false;
    while (!exited) {
        if (open > 0 && poll(fds, 2, 20) > 0)
            for (int i = 0; i < 2; ++i) {
                if (!(fds[i].revents & (POLLIN | POLLHUP))) continue;
                char buf[4096];
                const ssize_t n = read(fds[i].fd, buf, sizeof buf);
                if (n <= 0) fds[i].fd = -1, --open;
                else (i == 0 ? c.out : c.err).append(buf, size_t(n));
            }
        if (!marker && c.out.find(kMarker) != std::string::npos) marker = Clock::now();
        if (waitpid(pid, &status, WNOHANG) == pid) {
            exited = true;
            if (marker) c.markerToExit = std::chrono::duration<double>(Clock::now() - *marker).count();
            break;
        }
        if (open == 0) usleep(20000);
        const auto now = Clock::now();
        if ((marker && now - *marker > std::chrono::duration<double>(killAfter)) ||
            now - start > std::chrono::seconds(120)) {
            c.killed = true;
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            exited = true;
        }
    }
    for (int i = 0; i < 2; ++i) // what it wrote just before exiting
        for (char buf[4096]; fds[i].fd >= 0;) {
            const ssize_t n = read(fds[i].fd, buf, sizeof buf);
            if (n <= 0) break;
            (i == 0 ? c.out : c.err).append(buf, size_t(n));
        }
    close(outPipe[0]), close(errPipe[0]);
    c.exitCode = !c.killed && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return c;
}

} // namespace

TEST_F(FrameTimeLimit, WithoutALimitTheEndlessShaderHangs) {
    // The shader really does not end: without the limit the child is still rendering 4 s on.
    const Child c = runChild(0.0, 4.0);
    EXPECT_NE(c.out.find(kMarker), std::string::npos) << c.out << c.err;
    EXPECT_TRUE(c.killed) << "exit " << c.exitCode << "\n" << c.out << c.err;
}

TEST_F(FrameTimeLimit, AnEndlessShaderStopsTheRunWithOneErrorLineSoonAfterTheLimit) {
    const double limit = 2.0;
    const Child c = runChild(limit, limit + 30.0);
    ASSERT_FALSE(c.killed) << "the child hung past the limit\n" << c.out << c.err;
    EXPECT_NE(c.exitCode, 0) << c.out << c.err;
    EXPECT_EQ(c.out.find("the endless frame ended"), std::string::npos);
    const std::string line = "ssaolab: error: a frame took longer than 2 s (mine/endless.ao.glsl: the GPU work did "
                             "not finish; a shader that never ends?) - the run stops\n";
    EXPECT_NE(c.err.find(line), std::string::npos) << c.err;
    size_t errors = 0;
    for (size_t at = c.err.find("ssaolab: error:"); at != std::string::npos; at = c.err.find("ssaolab: error:", at + 1))
        ++errors;
    EXPECT_EQ(errors, 1u) << c.err;
    ASSERT_TRUE(c.markerToExit.has_value()) << c.out;
    std::printf("limit %.1f s: the child exited %.2f s after it started the frame\n", limit, *c.markerToExit);
    EXPECT_LE(*c.markerToExit, limit + 1.0); // a bound on a hang, not a timing: the watchdog fired
}

TEST_F(FrameTimeLimit, AFrameThatEndsRendersTheSameAoWithTheLimit) {
    Settings s = defaultSettings();
    auto r = makeRenderer(loadScene("builtin:showcase"), s, 96, 72);
    r->render();
    const Image without = readBack(r->texture("ao.raw"), 1);
    auto limited = makeRenderer(loadScene("builtin:showcase"), s, 96, 72);
    limited->setFrameTimeLimit(60.0);
    limited->render();
    const Image with = readBack(limited->texture("ao.raw"), 1);
    EXPECT_EQ(maxAbsDiff(without, with), 0.0);
    EXPECT_LT(stats(with).mean, 0.99); // something is occluded
}
