// Whole program on hostile input: broken third-party files, planted links, NaN options, bytes that are not UTF-8.
#include "cli_run.h"
#include "util/process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <regex>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace ssaotest;

TEST(CliHostile, EveryAssimpTestModelRendersOrFailsWithOneLine) {
    // Debian's assimp-testmodels: 53 glTF 1.0/2.0 files, many broken on purpose (indices out of
    // range, recursive nodes, wrong JSON types, missing .bin, infinities, Draco, glTF 1.0). Each
    // must render with finite AO or fail with one `ssaolab: error:` line: no signal, no hang.
    namespace fs = std::filesystem;
    const fs::path root = "/usr/share/assimp/models";
    ASSERT_TRUE(fs::is_directory(root / "glTF2")) << "install assimp-testmodels (.ci/install-deps.sh)";
    int rendered = 0, refused = 0;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        const std::string ext = e.path().extension().string();
        if (ext != ".gltf" && ext != ".glb") continue;
        const std::string out = outDir("assimp");
        const std::string base = std::string(SSAOLAB_TEST_TMP) + "/assimp";
        const std::string cmd = "timeout 60 '" + std::string(SSAOLAB_BINARY) + "' render --size 64x48 --quiet " +
                                "--timing-frames 1 --scene '" + e.path().string() + "' --out " + out + " >" +
                                base + ".out 2>" + base + ".err </dev/null";
        const int status = std::system(cmd.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << e.path() << " was killed by a signal";
        const int rc = WEXITSTATUS(status);
        std::ifstream in(base + ".err");
        std::stringstream err;
        err << in.rdbuf();
        const std::string text = err.str();
        EXPECT_NE(rc, 124) << e.path() << " hung";
        if (rc == 0) {
            ++rendered;
            std::ifstream m(out + "/metrics.json");
            const auto j = nlohmann::json::parse(m, nullptr, false);
            ASSERT_FALSE(j.is_discarded()) << e.path();
            for (const auto& [name, st] : j["buffers"].items())
                EXPECT_EQ(st.value("nonfinite", 0), 0) << e.path() << " " << name;
        } else {
            ++refused;
            EXPECT_EQ(rc, 1) << e.path() << ": " << text;
            EXPECT_EQ(text.rfind("ssaolab: error: ", 0), 0u) << e.path() << ": " << text;
            EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << e.path() << ": " << text;
        }
    }
    std::printf("assimp-testmodels: %d rendered, %d refused with one line\n", rendered, refused);
    EXPECT_GE(rendered + refused, 50);
    EXPECT_GE(rendered, 20);
}

TEST(CliHostile, OutputsNeverOverwriteWhatTheyMustNot) {
    // A symlink planted at a staging name inside --out made a render overwrite a file outside it.
    const std::string out = outDir("planted");
    std::filesystem::remove_all(out);
    std::filesystem::create_directories(out);
    const std::string victim = writeTemp("victim.txt", "precious");
    for (const char* staged : {"ao.raw.exr.exr-staged", "metrics.json.tmp1", "ao.raw.png.tmp-1-0"})
        ASSERT_EQ(::symlink(victim.c_str(), (out + "/" + staged).c_str()), 0);
    CliRun r = ssaolab("render --scene builtin:corner --size 64x36 --timing-frames 1 --quiet --out " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(victim), "precious");
    // tune --out a FIFO (or a device: /dev/null as root) replaced the node with a regular file.
    const std::string fifo = std::string(SSAOLAB_TEST_TMP) + "/tune_fifo";
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    r = ssaolab("tune --technique sao --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 "
                "--reference-rays 4 --knob sao.bias --quiet --out " + fifo);
    expectCleanFailure(r, "is not a regular file (a FIFO)");
    struct stat st {};
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO is still a FIFO";
    // Two renders into one --out at once: the EXR staging name had no process id ("truncated").
    const std::string shared = outDir("together");
    std::filesystem::remove_all(shared);
    const std::string cmd = std::string("'") + SSAOLAB_BINARY + "' render --scene builtin:showcase --size 160x90 "
                            "--timing-frames 1 --quiet --out " + shared;
    const std::string both = "(" + cmd + " & p1=$!; " + cmd + " & p2=$!; wait $p1; a=$?; wait $p2; b=$?; exit $((a + b)))";
    EXPECT_EQ(std::system(("bash -c '" + std::regex_replace(both, std::regex("'"), "'\\''") + "'").c_str()), 0);
    EXPECT_TRUE(std::filesystem::exists(shared + "/metrics.json"));
}

TEST(CliHostile, AFrameTimeLimitMustBeFiniteAndPositive) {
    // --frame-time-limit ends a headless run whose frame never finishes (gl/frame_watchdog.h):
    // nan would never trigger, 0 or less would stop every frame.
    expectCleanFailure(ssaolab("--frame-time-limit nan render --scene builtin:corner"), "not a finite number");
    expectCleanFailure(ssaolab("render --frame-time-limit 0 --scene builtin:corner"), "outside");
    expectCleanFailure(ssaolab("render --frame-time-limit -1 --scene builtin:corner"), "outside");
    expectCleanFailure(ssaolab("render --frame-time-limit inf --scene builtin:corner"), "not a finite number");
    expectCleanFailure(ssaolab("render --frame-time-limit 3601 --scene builtin:corner"), "outside");
}

TEST(CliHostile, NanOptionsAndNonUtf8NamesGiveOneLineOrAReport) {
    // `nan` passed CLI11's range checks: --tolerance nan switched the invariance check off.
    expectCleanFailure(ssaolab("stress --scene builtin:corner --tolerance nan"), "not a finite number");
    expectCleanFailure(ssaolab("--max-triangles nan render --scene builtin:corner"), "not a finite number");
    // A scene file name that is not UTF-8 ended in a bare json exception after the images, with no
    // metrics.json: JSON output replaces the bytes instead.
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/latin1";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string src = std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/";
    std::filesystem::copy_file(src + "cornellBox.gltf", dir + "/caf\xe9.gltf");
    std::filesystem::copy_file(src + "cornellBox.bin", dir + "/cornellBox.bin");
    const std::string out = outDir("latin1");
    std::filesystem::remove_all(out);
    const CliRun r = ssaolab("render --scene '" + dir + "/caf\xe9.gltf' --size 64x36 --timing-frames 1 --quiet --out " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json m = nlohmann::json::parse(slurp(out + "/metrics.json"));
    EXPECT_NE(m["scene"]["name"].get<std::string>().find("caf\xef\xbf\xbd.gltf"), std::string::npos); // U+FFFD
}

TEST(CliHostile, ThePageScriptsKeepANameInItsOwnCell) {
    // tools/layers_page.py writes docs/bench/layers.md from a bench run: a scene named with a table
    // separator, markup and a line break stays text in its own cell and heading.
    const std::string hostile = "a|b <script>*x*\nc";
    auto result = [&](int config) {
        return nlohmann::json{{"scene", hostile}, {"config", config}, {"rmse", 0.1}, {"time_ratio", 1.0},
                              {"pass_ms", {{"layers", nullptr}}}, {"rmse_screen", 0.05}, {"rmse_vs_oracle", 0.08}};
    };
    const nlohmann::json run = {
        {"cpu", "cpu"}, {"gl_renderer", "gl"}, {"hardware_threads", 2}, {"size", "64x36"}, {"views_per_scene", 1},
        {"frames", 1}, {"reference", {{"radius_scene", 0.05}, {"rays", 8}}}, {"build_type", "Release"},
        {"git_revision", "abc"},
        {"configurations",
         {{{"label", "learnopengl (baseline)"}, {"group", "baseline"}, {"keys", nlohmann::json::object()}, {"baseline", true}},
          {{"label", "preset=vbao-high"}, {"group", "vbao-high"}, {"keys", {{"preset", "vbao-high"}}}}}},
        {"results", {result(0), result(1)}}};
    const std::string in = writeTemp("layers_hostile.json", run.dump());
    const std::string dir = outDir("layers_hostile");
    std::filesystem::create_directories(dir);
    const std::string page = dir + "/layers.md";
    const ssao::ProgramRun r = ssao::runProgram({"/usr/bin/python3", std::string(SSAOLAB_SOURCE_DIR) + "/tools/layers_page.py", in, page},
                                                ssao::ChildStream::Discard, ssao::ChildStream::Capture);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string md = slurp(page);
    const std::string escaped = "a\\|b &lt;script&gt;\\*x\\* c";
    EXPECT_NE(md.find("## " + escaped + "\n"), std::string::npos) << md;
    EXPECT_NE(md.find("| " + escaped + " | vbao-high: 1.00x"), std::string::npos) << md;
    EXPECT_EQ(md.find("<script>"), std::string::npos);
}

// docs/stability.md's summary (tools/stress_findings.py) names the scene of the worst row: a hostile
// scene name lands escaped for Markdown, and a file that is not the stress run's JSON is one error line.
TEST(CliHostile, StressFindingsEscapeTheSceneTheyName) {
    const std::string hostile = "a|b <script>*x* c";
    const nlohmann::json row = {{"axis", "scale"},   {"variant", "x10"}, {"scene", hostile}, {"technique", "kernel"},
                                {"status", "ok"},    {"compared", false}, {"invariant", true}, {"rmse", 0.004},
                                {"nonfinite", 0},    {"outside", 0}};
    const std::string in = writeTemp("stress_hostile.json", nlohmann::json{{"rows", {row}}, {"tolerance", 0.02}, {"size", "64x36"}}.dump());
    const std::string tool = std::string(SSAOLAB_SOURCE_DIR) + "/tools/stress_findings.py";
    const ssao::ProgramRun r = ssao::runProgram({"/usr/bin/python3", tool, in}, ssao::ChildStream::Capture, ssao::ChildStream::Capture);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("largest RMSE 0.0040 (a\\|b &lt;script&gt;\\*x\\* c, kernel)"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("<script>"), std::string::npos);
    const ssao::ProgramRun bad = ssao::runProgram({"/usr/bin/python3", tool, writeTemp("stress_bad.json", "{\"rows\": 3}")},
                                                  ssao::ChildStream::Capture, ssao::ChildStream::Capture);
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.out.find("stress_findings: error:"), std::string::npos) << bad.out;
}
