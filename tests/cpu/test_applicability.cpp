// A setting that does nothing is said so (settings/applicability.h), and the first mistakes a new
// user makes - a typo in a key or a preset name, an image given as a scene or a preset - get a
// message that says what was given and what was expected (issue 42, items 1 and 8).
#include "scene/scene.h"
#include "scene/load/load_scene.h"
#include "settings/applicability.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "settings/preset_store.h"
#include "util/atomic_file.h"
#include "util/closest_name.h"
#include "util/file_kind.h"
#include "util/json_file.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace ssao;
using ssaotest::errorOf;
using ssaotest::writeTemp;

namespace {
bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}
Settings with(std::initializer_list<const char*> assignments) {
    Settings s = defaultSettings();
    for (const char* a : assignments)
        applyAssignment(s, a);
    return s;
}
std::string presetPath(const std::string& name) {
    return std::string(SSAOLAB_ASSET_DIR) + "/presets/" + name + ".json";
}
} // namespace

TEST(Applicability, AKeyOfAnotherTechniqueNamesWhatItNeeds) {
    const Settings s = with({"ao.technique=vbao"});
    const auto w = inapplicableKeys(s, {"gtao.steps", "vbao.steps", "ao.power"});
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "gtao.steps has no effect: it applies only when ao.technique = gtao (here vbao)");
}

TEST(Applicability, ADenoiserParameterUnderAnotherDenoiser) {
    const auto w = inapplicableKeys(with({"denoise.kind=box4"}), {"denoise.sigma", "denoise.sigma"});
    ASSERT_EQ(w.size(), 1u) << "each key once";
    EXPECT_TRUE(has(w[0], "denoise.kind = gaussian|bilateral (here box4)")) << w[0];
    EXPECT_TRUE(inapplicableKeys(with({"denoise.kind=gaussian"}), {"denoise.sigma"}).empty());
}

TEST(Applicability, AConditionOnARowThatItselfDoesNotApplyNamesTheRoot) {
    // ao.adaptive_px needs ao.adaptive = true, which the kernel does not take at all.
    const Settings s = with({"ao.technique=kernel", "ao.adaptive=true"});
    const Param* p = findParam("ao.adaptive_px");
    ASSERT_NE(p, nullptr);
    EXPECT_TRUE(has(inapplicableReason(*p, s), "ao.technique = ")) << inapplicableReason(*p, s);
    EXPECT_TRUE(has(inapplicableReason(*p, s), "(here kernel)")) << inapplicableReason(*p, s);
    EXPECT_EQ(inapplicableReason(*p, with({"ao.technique=gtao", "ao.adaptive=true"})), "");
    EXPECT_EQ(inapplicableReason(*p, with({"ao.technique=gtao"})), "ao.adaptive = true (here false)");
}

TEST(Applicability, AWorldRadiusUnderSceneModeSwitchesTheModeAndSaysSo) {
    Settings s = defaultSettings();
    ASSERT_EQ(s.ao.radiusMode, RadiusMode::Scene);
    const auto w = applyAssignments(s, {"ao.radius=2"});
    EXPECT_EQ(s.ao.radiusMode, RadiusMode::World);
    EXPECT_FLOAT_EQ(s.ao.radius, 2.0f);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(
        w[0],
        "--set ao.radius: ao.radius_mode switched from scene to world, the mode in which ao.radius applies");
    // The same for a screen radius; a radius already in its mode says nothing.
    Settings px = defaultSettings();
    EXPECT_EQ(applyAssignments(px, {"ao.radius_px=16"}).size(), 1u);
    EXPECT_EQ(px.ao.radiusMode, RadiusMode::Screen);
    Settings scene = defaultSettings();
    EXPECT_TRUE(applyAssignments(scene, {"ao.radius_scene=0.1"}).empty());
    EXPECT_EQ(scene.ao.radiusMode, RadiusMode::Scene);
}

TEST(Applicability, ARadiusWithAnExplicitModeIsNotSwitchedButReported) {
    Settings conflict = defaultSettings();
    const auto w = applyAssignments(conflict, {"ao.radius=2", "ao.radius_mode=scene"});
    EXPECT_EQ(conflict.ao.radiusMode, RadiusMode::Scene);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0],
              "--set ao.radius has no effect: it applies only when ao.radius_mode = world (here scene)");
    Settings agreed = defaultSettings();
    EXPECT_TRUE(applyAssignments(agreed, {"ao.radius_mode=world", "ao.radius=2"}).empty());
    EXPECT_EQ(agreed.ao.radiusMode, RadiusMode::World);
}

TEST(Applicability, TheCheckIsPureAndLaterAssignmentsDecide) {
    // Order does not matter for applicability: the technique set after its parameter still counts.
    const Settings s = with({"vbao.steps=4", "ao.technique=vbao"});
    const AssignmentCheck c = checkAssignments(s, {"vbao.steps", "ao.technique"});
    EXPECT_TRUE(c.warnings.empty());
    EXPECT_TRUE(c.settings == s);
    // The second condition of a row: gtao's steps are its own only at custom quality.
    const AssignmentCheck q =
        checkAssignments(with({"ao.technique=gtao", "gtao.steps=4"}), {"ao.technique", "gtao.steps"});
    ASSERT_EQ(q.warnings.size(), 1u);
    EXPECT_EQ(q.warnings[0],
              "gtao.steps has no effect: it applies only when gtao.quality = custom (here high)");
    // Two radii of different modes: the last one decides, the other is reported.
    const AssignmentCheck two =
        checkAssignments(with({"ao.radius=2", "ao.radius_px=8"}), {"ao.radius", "ao.radius_px"});
    EXPECT_EQ(two.settings.ao.radiusMode, RadiusMode::Screen);
    ASSERT_EQ(two.warnings.size(), 2u);
    EXPECT_TRUE(has(two.warnings[1], "ao.radius has no effect")) << two.warnings[1];
}

TEST(Applicability, APresetFileThatSetsAnInactiveKeyIsReportedByName) {
    const std::string path = writeTemp("applicability_box.json",
                                       R"({"denoise": {"kind": "box4", "sigma": 3}, "ao": {"power": 2}})");
    const Preset p = readPresetFile(path);
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_EQ(p.warnings[0],
              "preset " + path +
                  ": denoise.sigma has no effect: it applies only when denoise.kind = gaussian|bilateral "
                  "(here box4)");
}

TEST(Applicability, ACompletePresetReportsOnlyInactiveRowsMovedOffTheirDefaults) {
    // The app, tune and bench write every row: the inactive ones at their defaults are not the user's doing.
    Preset p;
    p.settings = with({"ao.technique=vbao"});
    const std::string clean = writeTemp("applicability_complete.json", presetToJson(p).dump());
    EXPECT_TRUE(readPresetFile(clean).warnings.empty());
    p.settings = with({"gtao.steps=4", "ao.technique=vbao"});
    const std::string moved = writeTemp("applicability_moved.json", presetToJson(p).dump());
    const auto w = readPresetFile(moved).warnings;
    ASSERT_EQ(w.size(), 1u);
    EXPECT_TRUE(has(w[0], "gtao.steps has no effect")) << w[0];
}

TEST(Applicability, EveryShippedPresetSetsOnlyKeysThatApply) {
    const PresetStore store = PresetStore::standard();
    int n = 0;
    for (const PresetEntry& e : store.entries())
        if (e.builtin) {
            EXPECT_TRUE(readPresetFile(e.path).warnings.empty())
                << e.name << ": " << readPresetFile(e.path).warnings[0];
            ++n;
        }
    EXPECT_GE(n, 20);
}

TEST(FirstHour, AMistypedKeyOrPresetNameSaysWhatWasMeant) {
    EXPECT_EQ(closestName("vbao-meduim", {"vbao-low", "vbao-medium", "vbao-high"}), "vbao-medium");
    EXPECT_EQ(didYouMean("zzzzzz", {"ao.radius"}), "");
    // A name in the wrong case is the name: "N8AO" was n8ao, whatever the word's length.
    EXPECT_EQ(closestName("N8AO", {"n8ao", "three-ssao", "three-gtao"}), "n8ao");
    EXPECT_EQ(closestName("THREE-GTAO", {"n8ao", "three-ssao", "three-gtao"}), "three-gtao");
    Settings s = defaultSettings();
    EXPECT_TRUE(has(errorOf([&] { applyAssignment(s, "ao.raduis=2"); }), "(did you mean ao.radius?)"))
        << errorOf([&] { applyAssignment(s, "ao.raduis=2"); });
    const std::string typo = writeTemp("applicability_typo.json", R"({"denoise": {"sigam": 2}})");
    EXPECT_TRUE(has(errorOf([&] { readPresetFile(typo); }),
                    "unknown key 'denoise.sigam' (did you mean denoise.sigma?)"))
        << errorOf([&] { readPresetFile(typo); });
    const std::string e = errorOf([] { PresetStore::standard().resolve("vbao-meduim"); });
    EXPECT_TRUE(has(e, "no preset named 'vbao-meduim' (did you mean vbao-medium?)")) << e;
}

TEST(FirstHour, TheFirstBytesSayWhatAFileIs) {
    EXPECT_EQ(binaryFileKind(std::string("\x89PNG\r\n\x1a\n....", 12)), "a PNG image");
    EXPECT_EQ(binaryFileKind("\xff\xd8\xff\xe0\x00\x10JFIF"), "a JPEG image");
    EXPECT_EQ(binaryFileKind(std::string("glTF\x02\0\0\0", 8)), "a GLB (binary glTF) scene");
    EXPECT_EQ(binaryFileKind(std::string("v/1\x01\x02\0\0\0", 8)), "an OpenEXR image");
    EXPECT_EQ(binaryFileKind(std::string("\x01\x80[[[[\0{{{", 11)), "binary data");
    EXPECT_EQ(binaryFileKind("{\"ao\": {\"radius\": 0.5}}\n"), "");
    EXPECT_EQ(binaryFileKind("o cube\nv 0 0 0\r\n\tf 1 2 3\n"), "");
    EXPECT_EQ(binaryFileKind(""), "");
}

TEST(FirstHour, AnImageGivenAsASceneOrAPresetIsNamedAsWhatItIs) {
    const std::string jpg =
        writeTemp("first_hour.jpg", std::string("\xff\xd8\xff\xe0\x00\x10JFIF\x00", 11) + "[[[[[[");
    EXPECT_EQ(errorOf([&] { loadScene(jpg); }),
              "scene " + jpg + " is a JPEG image, not a glTF scene (.gltf or .glb)");
    EXPECT_EQ(errorOf([&] { readPresetFile(jpg); }),
              "preset " + jpg + " is a JPEG image, not a preset (JSON text)");
    // Random bytes full of '[': was "nests arrays or objects deeper than 64 levels".
    std::string noise(4000, '[');
    for (size_t i = 0; i < noise.size(); i += 7)
        noise[i] = char(i % 251);
    const std::string bin = writeTemp("first_hour_buffer.bin", noise);
    const std::string e = errorOf([&] { loadScene(bin); });
    EXPECT_TRUE(has(e, "scene " + bin + " is binary data, not a glTF scene (.gltf or .glb)")) << e;
    EXPECT_TRUE(has(e, "give the .gltf that names it")) << e;
    // A preset given as the scene, and a scene given as the preset.
    const std::string preset = writeTemp("first_hour_preset.json", R"({"ao": {"power": 2}})");
    EXPECT_TRUE(has(errorOf([&] { loadScene(preset); }), "not a glTF scene"))
        << errorOf([&] { loadScene(preset); });
    const std::string gltf =
        writeTemp("first_hour_scene.gltf", R"({"asset": {"version": "2.0"}, "meshes": []})");
    EXPECT_EQ(errorOf([&] { readPresetFile(gltf); }), "preset " + gltf + " is a glTF scene, not a preset");
}

TEST(FirstHour, AFailedWriteNamesTheDestinationNotItsStagingFile) {
    // A name that fits but leaves no room for the staging suffix: the create fails (ENAMETOOLONG).
    const std::string path = std::string(SSAOLAB_TEST_TMP) + "/" + std::string(250, 'a') + ".json";
    std::filesystem::remove(path);
    const std::string e = errorOf([&] { writeFileAtomically(path, "x"); });
    EXPECT_TRUE(has(e, "cannot write " + path)) << e;
    EXPECT_FALSE(has(e, ".tmp-")) << e;
}
