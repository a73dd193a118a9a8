// A new user's first hour (issue 42): a setting that does nothing is a warning naming what it
// needs; a typo in a key or a preset name, or an image given where JSON or glTF is expected, is an
// error saying what was given and what was meant; bench and tune take --shaders as render does.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

using namespace ssaotest;

namespace {

const std::string kFast = " --scene builtin:corner --size 64x36 --timing-frames 1 --quiet";

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The `ssaolab: warning:` lines of a run's stderr about its settings (--set and presets; a
// warning about the view is another matter).
std::vector<std::string> warnings(const CliRun& r) {
    std::vector<std::string> out;
    std::istringstream in(r.err);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("ssaolab: warning: --set ", 0) == 0 || line.rfind("ssaolab: warning: preset ", 0) == 0)
            out.push_back(line);
    return out;
}

nlohmann::json metrics(const std::string& out) {
    return nlohmann::json::parse(slurp(out + "/metrics.json"));
}

} // namespace

TEST(CliFirstHour, AWorldRadiusUnderASceneRadiusPresetSwitchesTheModeAndSaysSo) {
    // Was: the render kept ao.radius_mode = scene and its radius of 0.05 x diagonal, silently.
    const std::string out = outDir("first_hour_radius");
    const CliRun r = ssaolab("render --preset vbao-medium --set ao.radius=2 --out " + out + kFast);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto w = warnings(r);
    ASSERT_EQ(w.size(), 1u) << r.err;
    EXPECT_EQ(w[0],
              "ssaolab: warning: --set ao.radius: ao.radius_mode switched from scene to world, the mode in "
              "which ao.radius applies");
    const nlohmann::json m = metrics(out);
    EXPECT_EQ(m["settings"]["ao"]["radius_mode"], "world");
    EXPECT_NEAR(m["radius"]["world_at_centre"].get<double>(), 2.0, 1e-6);
}

TEST(CliFirstHour, ARadiusWithAConflictingModeIsReportedUnused) {
    const CliRun r =
        ssaolab("render --preset vbao-medium --set ao.radius=2 --set ao.radius_mode=scene --out " +
                outDir("first_hour_conflict") + kFast);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto w = warnings(r);
    ASSERT_EQ(w.size(), 1u) << r.err;
    EXPECT_EQ(w[0],
              "ssaolab: warning: --set ao.radius has no effect: it applies only when ao.radius_mode = world "
              "(here scene)");
    EXPECT_EQ(metrics(outDir("first_hour_conflict"))["settings"]["ao"]["radius_mode"], "scene");
}

TEST(CliFirstHour, ASetThatDoesNothingIsAWarningNamingWhatItNeeds) {
    const std::string out = " --out " + outDir("first_hour_inactive") + kFast;
    CliRun r = ssaolab("render --preset vbao-medium --set gtao.steps=4" + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(warnings(r).size(), 1u) << r.err;
    EXPECT_EQ(warnings(r)[0], "ssaolab: warning: --set gtao.steps has no effect: it applies only when "
                              "ao.technique = gtao (here vbao)");
    r = ssaolab("render --preset learnopengl --set denoise.sigma=2" + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(warnings(r).size(), 1u) << r.err;
    EXPECT_TRUE(has(warnings(r)[0], "denoise.sigma has no effect: it applies only when denoise.kind = "
                                    "gaussian|bilateral (here box4)"))
        << r.err;
    // What applies says nothing.
    r = ssaolab("render --preset vbao-medium --set vbao.steps=4 --set ao.radius_scene=0.1" + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(warnings(r).empty()) << r.err;
}

TEST(CliFirstHour, APresetFileThatSetsAnInactiveKeyIsWarnedByName) {
    const std::string preset =
        writeTemp("first_hour_inactive.json",
                  R"({"ao": {"technique": "kernel"}, "denoise": {"kind": "box4", "sigma": 3}})");
    const CliRun r = ssaolab("render --preset " + preset + " --out " + outDir("first_hour_preset") + kFast);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(warnings(r).size(), 1u) << r.err;
    EXPECT_EQ(warnings(r)[0],
              "ssaolab: warning: preset " + preset +
                  ": denoise.sigma has no effect: it applies only when denoise.kind = gaussian|bilateral "
                  "(here box4)");
}

TEST(CliFirstHour, TuneWarnsAndTakesShaders) {
    // The warning comes before any work; the empty shader folder then fails the run by its name.
    const std::string empty = std::string(SSAOLAB_TEST_TMP) + "/first_hour_no_shaders";
    std::filesystem::create_directories(empty);
    const CliRun r =
        ssaolab("tune --technique sao --set gtao.steps=4 --shaders " + empty +
                " --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 --reference-rays 4 "
                "--knob sao.bias --quiet --out " +
                std::string(SSAOLAB_TEST_TMP) + "/first_hour_tuned.json");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    ASSERT_EQ(warnings(r).size(), 1u) << r.err;
    EXPECT_TRUE(has(warnings(r)[0],
                    "--set gtao.steps has no effect: it applies only when ao.technique = gtao (here sao)"))
        << r.err;
    EXPECT_TRUE(has(r.err, "ssaolab: error: shader file " + empty + "/")) << r.err;
}

TEST(CliFirstHour, BenchTakesShaders) {
    const std::string empty = std::string(SSAOLAB_TEST_TMP) + "/first_hour_no_shaders";
    std::filesystem::create_directories(empty);
    expectCleanFailure(ssaolab("bench --shaders " + empty +
                               " --scene builtin:corner --size 64x36 --views 1 --frames 1 "
                               "--warmup 0 --reference-rays 4 --no-plot --quiet --out " +
                               outDir("first_hour_bench")),
                       "shader file " + empty + "/");
}

TEST(CliFirstHour, APresetASweepOpensIsWarnedByName) {
    // The warning comes once the sweep is read; the empty shader folder then ends the run early.
    const std::string preset =
        writeTemp("first_hour_sweep_preset.json",
                  R"({"ao": {"technique": "kernel"}, "denoise": {"kind": "box4", "sigma": 3}})");
    const std::string sweep = writeTemp("first_hour_sweep.json",
                                        R"({"groups": [{"name": "mine", "preset": ")" + preset + R"("}]})");
    const std::string empty = std::string(SSAOLAB_TEST_TMP) + "/first_hour_no_shaders";
    std::filesystem::create_directories(empty);
    const CliRun r =
        ssaolab("bench --sweep " + sweep + " --shaders " + empty + " --scene builtin:corner --size 64x36 " +
                "--views 1 --frames 1 --warmup 0 --reference-rays 4 --no-plot --quiet --out " +
                outDir("first_hour_sweep"));
    EXPECT_EQ(r.exitCode, 1) << r.err;
    ASSERT_EQ(warnings(r).size(), 1u) << r.err;
    EXPECT_TRUE(has(warnings(r)[0], "preset " + preset + ": denoise.sigma has no effect")) << r.err;
}

TEST(CliFirstHour, AMistypedKeyOrPresetNameSaysWhatWasMeant) {
    const std::string out = " --out " + outDir("first_hour_typo");
    expectCleanFailure(ssaolab("render --preset vbao-meduim" + out),
                       "no preset named 'vbao-meduim' (did you mean vbao-medium?)");
    expectCleanFailure(ssaolab("render --set ao.raduis=2" + out),
                       "unknown parameter 'ao.raduis' (did you mean ao.radius?)");
    expectCleanFailure(
        ssaolab("render --preset " + writeTemp("first_hour_typo.json", R"({"ao": {"pwer": 2}})") + out),
        "unknown key 'ao.pwer' (did you mean ao.power?)");
}

TEST(CliFirstHour, AFileOfAnotherKindIsNamedAsWhatItIs) {
    const std::string out = " --out " + outDir("first_hour_kind");
    const std::string jpg =
        writeTemp("first_hour.jpg", std::string("\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01", 12) + "[[[[");
    const std::string png = writeTemp("first_hour.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    std::string noise(3000, '[');
    for (size_t i = 0; i < noise.size(); i += 5)
        noise[i] = char(i * 37 % 256);
    const std::string bin = writeTemp("first_hour.bin", noise);
    expectCleanFailure(ssaolab("render --scene " + jpg + out),
                       "scene " + jpg + " is a JPEG image, not a glTF scene (.gltf or .glb)");
    // Was: "nests arrays or objects deeper than 64 levels".
    expectCleanFailure(ssaolab("render --scene " + bin + out),
                       "scene " + bin + " is binary data, not a glTF scene");
    expectCleanFailure(ssaolab("render --preset " + png + out),
                       "preset " + png + " is a PNG image, not a preset (JSON text)");
    expectCleanFailure(ssaolab("bench --sweep " + jpg + out),
                       "sweep " + jpg + " is a JPEG image, not a sweep (JSON text)");
    const std::string gltf = writeTemp("first_hour_scene.gltf", R"({"asset": {"version": "2.0"}})");
    expectCleanFailure(ssaolab("render --preset " + gltf + out),
                       "preset " + gltf + " is a glTF scene, not a preset");
}

TEST(CliFirstHour, AFailedWriteNamesTheDestinationNotAStagingFile) {
    // Was: "cannot create NAME.json.tmp-12345-0 (File name too long)".
    const std::string dest = std::string(SSAOLAB_TEST_TMP) + "/" + std::string(250, 't') + ".json";
    std::filesystem::remove(dest);
    const CliRun r =
        ssaolab("tune --technique sao --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 "
                "--reference-rays 4 --knob sao.bias --quiet --out " +
                dest);
    expectCleanFailure(r, "cannot write " + dest + ": ");
    EXPECT_FALSE(has(r.err, ".tmp-")) << r.err;
}
