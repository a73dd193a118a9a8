// Presets carry their scene and size; `render` and the app find presets by name in the same
// places; an installed binary runs from anywhere.
#include "engine_test_util.h"
#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>

using ssaotest::slurp;
using ssaotest::writeTemp;
namespace fs = std::filesystem;

namespace {
int run(const std::string& cmd, std::string* output = nullptr) {
    const std::string log = std::string(SSAOLAB_TEST_TMP) + "/presets_cmd.log";
    const int status = std::system((cmd + " >" + log + " 2>&1 </dev/null").c_str());
    if (output) *output = slurp(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
std::string bin() {
    return std::string("'") + SSAOLAB_BINARY + "'";
}
nlohmann::json metrics(const std::string& dir) {
    return nlohmann::json::parse(slurp(dir + "/metrics.json"));
}
} // namespace

TEST(CliPresets, APresetCarriesItsSceneAndSizeUnlessOverridden) {
    const std::string cornell = std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf";
    const std::string preset =
        writeTemp("with_scene_size.json",
                  R"({"scene": ")" + cornell + R"(", "size": [200, 120], "kernel": {"samples": 16}})");
    const std::string out = std::string(SSAOLAB_TEST_TMP) + "/preset_scene";
    std::string log;
    ASSERT_EQ(run(bin() + " render --timing-frames 1 --preset '" + preset + "' --out " + out, &log), 0)
        << log;
    auto m = metrics(out);
    EXPECT_EQ(m["scene"]["name"], cornell) << "not showcase as a speck";
    EXPECT_EQ(m["size"], nlohmann::json({200, 120}));
    EXPECT_GT(m["geometry_pixels"].get<long>(), 200 * 120 / 10);
    // Command-line options win.
    ASSERT_EQ(run(bin() + " render --timing-frames 1 --preset '" + preset +
                      "' --scene builtin:corner --size 64x32 --out " + out,
                  &log),
              0)
        << log;
    m = metrics(out);
    EXPECT_EQ(m["scene"]["name"], "builtin:corner");
    EXPECT_EQ(m["size"], nlohmann::json({64, 32}));
    // A relative scene path is relative to the preset file.
    fs::create_directories(std::string(SSAOLAB_TEST_TMP) + "/rel");
    const std::string rel = fs::relative(cornell, std::string(SSAOLAB_TEST_TMP) + "/rel").string();
    const std::string relPreset =
        writeTemp("rel/relative.json", R"({"scene": ")" + rel + R"(", "size": [64, 40]})");
    ASSERT_EQ(
        run("cd / && " + bin() + " render --timing-frames 1 --preset '" + relPreset + "' --out " + out, &log),
        0)
        << log;
    EXPECT_TRUE(fs::equivalent(metrics(out)["scene"]["name"].get<std::string>(), cornell))
        << metrics(out)["scene"];
}

TEST(CliPresets, RenderFindsPresetsSavedInTheAppByName) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/user_presets_cli";
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::ofstream(dir + "/my look.json")
            << R"({"name": "my look", "size": [96, 54], "ao": {"power": 2}})";
    }
    const std::string out = std::string(SSAOLAB_TEST_TMP) + "/preset_named";
    std::string log;
    ASSERT_EQ(run("SSAOLAB_PRESET_DIR='" + dir + "' " + bin() +
                      " render --timing-frames 1 --preset 'my look' --out " + out,
                  &log),
              0)
        << log;
    EXPECT_EQ(metrics(out)["settings"]["ao"]["power"], 2.0);
    EXPECT_EQ(metrics(out)["size"], nlohmann::json({96, 54}));
    // --preset-dir does the same; a seed preset name still wins over a user file of that name.
    ASSERT_EQ(
        run(bin() + " render --timing-frames 1 --preset-dir '" + dir + "' --preset 'my look' --out " + out,
            &log),
        0)
        << log;
    ASSERT_EQ(run(bin() + " render --timing-frames 1 --size 64x36 --preset learnopengl --out " + out, &log),
              0)
        << log;
    EXPECT_EQ(metrics(out)["settings"]["ao"]["radius_mode"], "world");
}

TEST(CliInstall, TheInstalledTreeRunsFromAnywhereWithoutTheSources) {
    const std::string base = std::string(SSAOLAB_TEST_TMP) + "/install";
    fs::remove_all(base);
    std::string log;
    ASSERT_EQ(run(std::string("'") + SSAOLAB_CMAKE + "' --install '" + SSAOLAB_BUILD_DIR + "' --prefix '" +
                      base + "/prefix'",
                  &log),
              0)
        << log;
    // Relocatable: move the whole prefix elsewhere, then run from an unrelated folder.
    fs::rename(base + "/prefix", base + "/moved");
    const std::string exe = base + "/moved/bin/ssaolab";
    ASSERT_TRUE(fs::exists(exe));
    ASSERT_EQ(run("cd / && '" + exe + "' paths", &log), 0) << log;
    EXPECT_NE(log.find("(installed)"), std::string::npos) << log;
    const std::string data = fs::weakly_canonical(base + "/moved/share/ssaolab").string();
    EXPECT_NE(log.find("shaders    " + data + "/shaders"), std::string::npos)
        << "not the source tree's: " << log;
    const std::string out = base + "/out";
    ASSERT_EQ(run("cd / && '" + exe + "' render --preset seed003 --size 64x36 --timing-frames 1 --out " + out,
                  &log),
              0)
        << log;
    EXPECT_TRUE(fs::exists(out + "/ao.denoised.png"));
    // The web engines run from the installed tables, scripts and pinned packages.
    using ssaotest::kModules, ssaotest::modulesInstalled, ssaotest::nodeRuns;
    NEED_MODULES();
    const std::string scene = ssaotest::writeCornerGltf("installed_engine.gltf");
    ASSERT_EQ(run("cd / && '" + exe + "' tune --engine n8ao --scene '" + scene + "' --size 64x36 --views 2 --rounds 1 --grid 3 "
                  "--knob aoRadius --reference-rays 8 --timing-frames 1 --save-overfit --quiet --out " + base + "/engine.json", &log),
              0)
        << log;
    EXPECT_TRUE(fs::exists(base + "/engine.js"));
}
