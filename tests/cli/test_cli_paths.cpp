// Every path option of every command, taken from the program's own CLI definitions (`ssaolab
// options`, hidden), tried with what a hostile user or a stale folder hands it: a FIFO, a folder,
// a symlink to a private file, a device node, /dev/full and a name that is not UTF-8. Each run ends
// with exit 0 or one `ssaolab: error:` line and exit 1 (no signal, no hang), never shows the private
// file's bytes, and changes nothing but its own output.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <map>
#include <set>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

const char* kSecret = "SSAOLAB-PRIVATE-7f3a9c";
const std::set<std::string> kPathTypes = {"FILE", "FILE...", "DIR", "DIR...", "OUT-FILE", "OUT-DIR"};

struct PathOption {
    std::string command, option, type;
    bool output() const { return type.rfind("OUT-", 0) == 0; }
};

// The options `ssaolab options` lists: every non-flag option must say what it takes.
std::vector<PathOption> pathOptions() {
    CliRun r = ssaolab("options");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::vector<PathOption> out;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
        const auto j = nlohmann::json::parse(line);
        const std::string type = j["type"].get<std::string>();
        const std::string kind = type.substr(0, type.find(':'));
        EXPECT_TRUE(j["flag"].get<bool>() || type != "TEXT")
            << "ssaolab " << j["command"] << " " << j["option"] << " takes bare TEXT: give it a type name "
            << "(a path kind of app/cli/cli_util.h, or what the text is)";
        if (kPathTypes.count(kind)) out.push_back({j["command"], j["option"], kind});
    }
    return out;
}

// A command line that runs `command` quickly and well on builtin:corner; the option under test
// replaces its own entry.
struct Recipe {
    std::vector<std::pair<std::string, std::string>> options;
    std::string extra;
};

std::string shq(const std::string& s) {
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// `ssaolab ARGS` run inside `dir` under a 60 s timeout (124: it hung), both streams captured.
CliRun runIn(const fs::path& dir, const std::string& args) {
    return ssaolab(args, "cd " + shq(dir.string()) + " && timeout 60");
}

// The sandbox's entries with their kinds (links not followed) and the private file's bytes.
std::map<std::string, std::string> snapshot(const fs::path& root) {
    std::map<std::string, std::string> out;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const auto st = it->symlink_status();
        std::string kind = std::to_string(int(st.type()));
        if (fs::is_symlink(st)) kind += "->" + fs::read_symlink(it->path()).string();
        out[fs::relative(it->path(), root).string()] = kind;
    }
    return out;
}

class PathOptions : public ::testing::Test {
  protected:
    // Per test: ctest runs the two tests here at the same time.
    const std::string name_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::path box_ = fs::path(SSAOLAB_TEST_TMP) / ("paths_box_" + name_);
    std::string shard_ = std::string(SSAOLAB_TEST_TMP) + "/paths_shard_" + name_;
    std::string sweep_;

    void SetUp() override {
        sweep_ = writeTemp("paths_sweep_" + name_ + ".json", R"({"name": "paths", "groups": [{"name": "k", "set": {"kernel.samples": 8}}]})");
        fs::remove_all(shard_);
        CliRun r = ssaolab("bench " + common("bench") + " --out " + shard_);
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }

    std::string common(const std::string& command) const {
        if (command == "render") return "--size 64x36 --timing-frames 1 --quiet --reference --reference-rays 4";
        if (command == "bench")
            return "--scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 --reference-rays 4 --no-plot "
                   "--quiet --sweep " + sweep_;
        return "";
    }

    Recipe recipe(const std::string& command) const {
        if (command == "render") return {{{"--scene", "builtin:corner"}, {"--out", "run_out"}}, common("render")};
        if (command == "bench") return {{{"--out", "run_out"}}, common("bench")};
        if (command == "bench merge") return {{{"dirs", shard_}, {"--out", "run_out"}}, "--no-plot --quiet"};
        if (command == "tune")
            return {{{"--scene", "builtin:corner"}, {"--out", "run_out.json"}},
                    "--technique sao --size 64x36 --views 2 --rounds 1 --grid 3 --reference-rays 4 --knob sao.bias --quiet"};
        if (command == "skips")
            return {{{"--scene", "builtin:corner"}, {"--out", "run_out"}}, "--size 64x36 --frames 1 --reference-rays 4"};
        if (command == "stress")
            return {{{"--scene", "builtin:corner"}, {"--out", "run_out"}}, "--technique sao --size 64x36"};
        if (command == "view")
            return {{{"--scene", "builtin:corner"}, {"--screenshot", "run_out.png"}}, "--size 320x240 --frames 1"};
        if (command == "probe-technique")
            return {{{"file", std::string(SSAOLAB_SOURCE_DIR) + "/examples/techniques/learnopengl.ao.glsl"}}, "--size 32x18"};
        if (command == "compile-glsl")
            return {{{"name", "x.frag"}, {"--source", writeTemp("paths_compile_source.frag", "#version 450 core\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(1.0); }\n")}},
                    ""};
        if (command.empty()) // the global options (--technique-dir), given to a render
            return {{}, "render --scene builtin:corner --out run_out " + common("render")};
        ADD_FAILURE() << "no recipe for `ssaolab " << command << "`: add one so its path options are tried";
        return {};
    }

    // The hostile paths, made afresh in the sandbox; the value to pass for each.
    std::vector<std::pair<std::string, std::string>> makeBox(bool output) {
        fs::remove_all(box_);
        fs::create_directories(box_ / "folder");
        std::ofstream(box_ / "private.txt") << kSecret;
        ::chmod((box_ / "private.txt").c_str(), 0600);
        fs::create_symlink(box_ / "private.txt", box_ / "private-link");
        EXPECT_EQ(::mkfifo((box_ / "fifo").c_str(), 0600), 0);
        return {{"fifo", "fifo"},
                {"folder", "folder"},
                {"private link", "private-link"},
                {"device", output ? "/dev/null" : "/dev/zero"},
                {"full device", "/dev/full"},
                {"non-UTF-8 name", "caf\xe9\xff"}};
    }

    std::string line(const PathOption& p, const std::string& value) const {
        const Recipe r = recipe(p.command);
        std::string args = p.command + " " + r.extra;
        for (const auto& [opt, v] : r.options)
            if (opt != p.option) args += (opt[0] == '-' ? " " + opt + " " : " ") + shq(v);
        return args + (p.option[0] == '-' ? " " + p.option + " " : " ") + shq(value);
    }

    // What every run must keep, whatever its exit code.
    void judgeRun(const PathOption& p, const std::string& kind, const CliRun& r) {
        const std::string what = "ssaolab " + p.command + " " + p.option + " <" + kind + ">";
        EXPECT_FALSE(r.signaled) << what << ": " << r.err;
        EXPECT_NE(r.exitCode, 124) << what << " hung";
        EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 1) << what << " exited " << r.exitCode << ": " << r.err;
        if (r.exitCode == 1) { // one error line, last; before it at most warnings about the settings
            std::istringstream lines(r.err);
            std::vector<std::string> all;
            for (std::string l; std::getline(lines, l);)
                all.push_back(l);
            ASSERT_FALSE(all.empty()) << what << " failed without a word";
            EXPECT_EQ(all.back().rfind("ssaolab: error: ", 0), 0u) << what << ": " << r.err;
            for (size_t i = 0; i + 1 < all.size(); ++i)
                EXPECT_EQ(all[i].rfind("ssaolab: warning: ", 0), 0u) << what << ": " << r.err;
        }
        // A hostile path the command must write, or must read as its input, is refused, never used.
        const bool primaryRead = p.type != "DIR" && !p.output();
        const bool fileKind = p.type == "FILE" || p.type == "FILE..." || p.type == "OUT-FILE";
        const bool refused = kind == "fifo" || kind == "device" || kind == "full device" ||
                             (kind == "private link" && p.output()) || (kind == "folder" && fileKind);
        if (refused && (p.output() || primaryRead)) {
            EXPECT_EQ(r.exitCode, 1) << what << " was not refused: " << r.out << r.err;
        }
        EXPECT_EQ(r.out.find(kSecret), std::string::npos) << what << " printed the private file";
        EXPECT_EQ(r.err.find(kSecret), std::string::npos) << what << " printed the private file";
    }

    // Nothing changed but the runs' own outputs (the default one, or the hostile paths they were given).
    void judgeBox(const std::string& what, const std::map<std::string, std::string>& before,
                  const std::vector<std::string>& own) {
        const auto after = snapshot(box_);
        for (const auto& [path, type] : before) {
            const auto it = after.find(path);
            EXPECT_TRUE(it != after.end() && it->second == type) << what << " changed or removed " << path;
        }
        for (const auto& [path, type] : after) {
            if (before.count(path)) continue;
            bool mine = path.rfind("run_out", 0) == 0;
            for (const auto& o : own)
                mine = mine || path.rfind(o, 0) == 0;
            EXPECT_TRUE(mine) << what << " wrote " << path << " outside its output";
            if (fs::is_regular_file(fs::symlink_status(box_ / path))) {
                EXPECT_EQ(slurp((box_ / path).string()).find(kSecret), std::string::npos)
                    << what << " copied the private file into " << path;
            }
        }
        EXPECT_EQ(slurp((box_ / "private.txt").string()), kSecret) << what << " changed the private file";
        EXPECT_TRUE(fs::is_character_file("/dev/full") && fs::is_character_file("/dev/null")) << what;
    }
};

} // namespace

TEST_F(PathOptions, EveryPathOptionOfEveryHeadlessCommandRefusesHostilePathsWithOneLine) {
    const auto options = pathOptions();
    ASSERT_GE(options.size(), 20u); // render, bench, merge, tune, skips, stress and view each have some
    int runs = 0;
    for (const PathOption& p : options) {
        if (p.command == "view") continue; // needs a display: the test below
        for (const auto& [kind, value] : makeBox(p.output())) {
            makeBox(p.output());
            const auto before = snapshot(box_);
            const CliRun r = runIn(box_, line(p, value));
            judgeRun(p, kind, r);
            judgeBox("ssaolab " + p.command + " " + p.option + " <" + kind + ">", before,
                     p.output() ? std::vector<std::string>{value} : std::vector<std::string>{});
            ++runs;
        }
    }
    std::printf("%d hostile runs over %zu path options\n", runs, options.size());
}

TEST_F(PathOptions, EveryPathOptionOfTheWindowRefusesHostilePathsWithOneLine) {
    // The explorer under one virtual display: every case in one script, judged one by one.
    std::vector<std::pair<PathOption, std::string>> cases;
    std::vector<std::string> own;
    std::string script;
    const std::string tmp = std::string(SSAOLAB_TEST_TMP) + "/paths_view_case";
    for (const PathOption& p : pathOptions()) {
        if (p.command != "view") continue;
        for (const auto& [kind, value] : makeBox(p.output())) {
            const size_t i = cases.size();
            cases.push_back({p, kind});
            if (p.output()) own.push_back(value);
            const std::string base = tmp + std::to_string(i);
            script += "cd " + shq(box_.string()) + " && timeout 60 " + shq(SSAOLAB_BINARY) + " " + line(p, value) +
                      " >" + base + ".out 2>" + base + ".err </dev/null; echo $? >" + base + ".rc\n";
        }
    }
    ASSERT_GE(cases.size(), 6u * 5);
    makeBox(false);
    const auto before = snapshot(box_);
    const std::string file = writeTemp("paths_view_" + name_ + ".sh", script);
    ASSERT_EQ(underXvfb("sh " + file, "paths"), 0);
    for (size_t i = 0; i < cases.size(); ++i) {
        CliRun r;
        const std::string base = tmp + std::to_string(i);
        const std::string rc = slurp(base + ".rc");
        ASSERT_FALSE(rc.empty()) << "case " << i << " never ran";
        r.exitCode = std::atoi(rc.c_str());
        r.signaled = r.exitCode > 128 && r.exitCode != 124;
        r.out = slurp(base + ".out"), r.err = slurp(base + ".err");
        judgeRun(cases[i].first, cases[i].second, r);
    }
    judgeBox("ssaolab view", before, own);
}

TEST(PathOptionsInside, AFifoOrALinkInsideTheShaderFolderIsRefusedNotWaitedOn) {
    // A folder the user points at holds what anyone put there: a FIFO where a shader should be
    // blocked the render for ever; a link to a private file must not reach an error line.
    for (const std::string kind : {"fifo", "private link"}) {
        const fs::path dir = fs::path(SSAOLAB_TEST_TMP) / ("paths_shaders_" + std::to_string(kind.size()));
        fs::remove_all(dir);
        fs::copy(fs::path(SSAOLAB_SOURCE_DIR) / "shaders", dir, fs::copy_options::recursive);
        const fs::path victim = dir / "passes" / "composite.frag";
        fs::remove(victim);
        if (kind == "fifo") {
            ASSERT_EQ(::mkfifo(victim.c_str(), 0600), 0);
        } else {
            std::ofstream(dir / "private.txt") << kSecret;
            fs::create_symlink(dir / "private.txt", victim);
        }
        const CliRun r = ssaolab("render --scene builtin:corner --size 64x36 --timing-frames 1 --quiet --shaders " +
                                     shq(dir.string()) + " --out " + outDir("paths_shaders"),
                                 "timeout 60");
        EXPECT_NE(r.exitCode, 124) << kind << " hung";
        EXPECT_EQ(r.err.find(kSecret), std::string::npos) << kind << ": " << r.err;
        if (kind == "fifo") {
            expectCleanFailure(r, "is a FIFO, not a regular file");
        } else {
            EXPECT_TRUE(r.exitCode == 1 && std::count(r.err.begin(), r.err.end(), '\n') == 1) << r.err;
        }
    }
}
