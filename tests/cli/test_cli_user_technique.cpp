// A user technique through the whole program: every headless command takes it from
// --technique-dir (render, bench with a sweep over its rows and in shards joined by merge, tune),
// a compile error is one line naming FILE:LINE, a refused file is a warning and choosing it the
// error, and a preset saved with it names the file and says when the file changed.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

const std::string kExamples = std::string(SSAOLAB_SOURCE_DIR) + "/examples/techniques";

std::string lastLine(const std::string& s) {
    std::string t = s;
    while (!t.empty() && t.back() == '\n') t.pop_back();
    return t.substr(t.rfind('\n') == std::string::npos ? 0 : t.rfind('\n') + 1);
}

std::string folder(const std::string& name) {
    const std::string dir = outDir(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

} // namespace

TEST(CliUserTechnique, RenderBenchShardsMergeAndTuneTakeItFromTheFolder) {
    const std::string g = "--technique-dir '" + kExamples + "' ";
    const std::string out = folder("user_cli");
    CliRun r = ssaolab(g + "render --scene builtin:corner --size 96x54 --set ao.technique=user.xegtao "
                           "--set user.xegtao.slices=2 --timing-frames 1 --quiet --reference --reference-rays 8 --out " + out + "/render");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json m = nlohmann::json::parse(slurp(out + "/render/metrics.json"));
    EXPECT_EQ(m.dump().find("user.xegtao") != std::string::npos, true);

    const std::string sweep = writeTemp("user_cli_sweep.json",
        R"({"name": "user", "groups": [{"name": "x", "set": {"ao.technique": "user.xegtao"}, "vary": {"user.xegtao.slices": [1, 2]}}]})");
    const std::string common = "bench --scene builtin:corner --size 64x36 --views 1 --frames 1 --warmup 0 "
                               "--reference-rays 4 --no-plot --quiet --sweep " + sweep;
    for (int k = 1; k <= 2; ++k) {
        r = ssaolab(g + common + " --shard " + std::to_string(k) + "/2 --out " + out + "/shard" + std::to_string(k));
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    r = ssaolab(g + "bench merge " + out + "/shard1 " + out + "/shard2 --no-plot --quiet --out " + out + "/merged");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string summary = slurp(out + "/merged/summary.csv");
    EXPECT_NE(summary.find("ao.technique=user.xegtao user.xegtao.slices=1"), std::string::npos) << summary;
    EXPECT_NE(summary.find("ao.technique=user.xegtao user.xegtao.slices=2"), std::string::npos) << summary;
    EXPECT_NE(summary.find("user.learnopengl defaults"), std::string::npos) << summary; // every technique at its defaults

    r = ssaolab(g + "tune --technique user.xegtao --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 "
                    "--reference-rays 4 --knob user.xegtao.falloff_range --quiet --save-overfit --out " + out + "/tuned.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json tuned = nlohmann::json::parse(slurp(out + "/tuned.json"));
    EXPECT_EQ(tuned["ao"]["technique"], "user.xegtao");
    EXPECT_EQ(tuned["technique_file"]["file"], "xegtao.ao.glsl");
    EXPECT_TRUE(tuned.contains("user.xegtao"));
    EXPECT_FALSE(tuned.contains("user.learnopengl"));
    // Without the folder the preset fails naming the technique and its file.
    r = ssaolab("render --preset " + out + "/tuned.json --size 64x36 --out " + out + "/nofolder");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(lastLine(r.err).find("user technique user.xegtao (xegtao.ao.glsl), which is not loaded"), std::string::npos)
        << r.err;
}

TEST(CliUserTechnique, ACompileErrorAndARefusedFileAreOneLineNamingFileAndLine) {
    const std::string dir = folder("user_cli_errors");
    std::ofstream(dir + "/broken.ao.glsl") << "/*ssaolab\ninterface = 1;\n*/\nfloat ssaoUserAo() {\n    return nope;\n}\n";
    std::ofstream(dir + "/bad.ao.glsl") << "/*ssaolab\ninterface = 1;\nuniform float k < ui_min = 1; ui_max = 0; > = 0;\n*/\n";
    const std::string g = "--technique-dir '" + dir + "' ";
    CliRun r = ssaolab(g + "render --scene builtin:corner --size 64x36 --set ao.technique=user.broken --out " + dir + "/o1");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(lastLine(r.err).rfind("ssaolab: error: " + dir + "/broken.ao.glsl:5: ", 0), 0u) << r.err;
    // The refused file: a warning on every run, and the error when it is chosen.
    r = ssaolab(g + "render --scene builtin:corner --size 64x36 --set ao.technique=user.bad --out " + dir + "/o2");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("ssaolab: warning: " + dir + "/bad.ao.glsl:3: "), std::string::npos) << r.err;
    EXPECT_NE(lastLine(r.err).find("technique user.bad was not loaded: " + dir + "/bad.ao.glsl:3: "), std::string::npos)
        << r.err;
    // A named folder that does not exist is refused.
    r = ssaolab("--technique-dir '" + dir + "/absent' params");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(lastLine(r.err).find("does not exist"), std::string::npos) << r.err;
}

TEST(CliUserTechnique, APresetSavedWithItSaysWhenTheFileHasChanged) {
    const std::string dir = folder("user_cli_changed");
    fs::copy_file(kExamples + "/xegtao.ao.glsl", dir + "/mine.ao.glsl");
    const std::string g = "--technique-dir '" + dir + "' ";
    CliRun r = ssaolab(g + "tune --technique user.mine --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 "
                           "--reference-rays 4 --knob user.mine.falloff_range --quiet --save-overfit --out " + dir + "/p.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = ssaolab(g + "render --preset " + dir + "/p.json --size 64x36 --quiet --out " + dir + "/same");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("has changed"), std::string::npos) << r.err;
    std::ofstream(dir + "/mine.ao.glsl", std::ios::app) << "\n// an edit\n";
    r = ssaolab(g + "render --preset " + dir + "/p.json --size 64x36 --quiet --out " + dir + "/changed");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("ssaolab: warning: preset " + dir + "/p.json: mine.ao.glsl has changed since the preset was saved"),
              std::string::npos)
        << r.err;
}
