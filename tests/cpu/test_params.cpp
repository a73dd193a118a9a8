#include "settings/params.h"
#include "settings/preset.h"
#include "techniques/technique.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

using namespace ssao;
using ssaotest::errorOf;
using ssaotest::writeTemp;

TEST(ParamTable, KeysUniqueDefaultsInRangeAndDocumented) {
    std::set<std::string> keys;
    for (const auto& p : paramTable()) {
        EXPECT_TRUE(keys.insert(p.key).second) << p.key;
        EXPECT_GE(p.def, p.min) << p.key;
        EXPECT_LE(p.def, p.max) << p.key;
        EXPECT_FALSE(p.help.empty()) << p.key;
        EXPECT_FALSE(p.label.empty()) << p.key;
        EXPECT_NE(p.key.find('.'), std::string::npos) << p.key;
        if (p.type == Param::Type::Enum) {
            EXPECT_EQ(p.max, double(p.choices.size() - 1)) << p.key;
        }
    }
    // The issue's required knobs are all in the table.
    for (const char* k : {"kernel.shape",
                          "kernel.separable",
                          "kernel.samples",
                          "ao.radius",
                          "ao.radius_mode",
                          "ao.radius_scene",
                          "ao.radius_px",
                          "kernel.bias",
                          "kernel.range_check",
                          "ao.power",
                          "kernel.noise",
                          "kernel.seed",
                          "kernel.position_source",
                          "denoise.kind",
                          "denoise.sigma",
                          "denoise.spacing",
                          "ao.technique",
                          "ao.resolution",
                          "gbuffer.position_format",
                          "gbuffer.normal_format"})
        EXPECT_NE(findParam(k), nullptr) << k;
    EXPECT_EQ(findParam("kernel.samples")->max, 256.0); // not capped at 64
}

TEST(ParamTable, DefaultsRoundTripThroughJson) {
    Settings d = defaultSettings();
    Settings back = defaultSettings();
    back.ao.radius = 9.0f; // make sure applyJson really writes
    applyJson(back, toJson(d), "test");
    EXPECT_TRUE(back == d);
}

TEST(ParamTable, EveryValueOfEveryParameterRoundTrips) {
    for (const auto& p : paramTable()) {
        std::vector<double> values = {p.min, p.max, p.def};
        if (p.type == Param::Type::Float) values.push_back(p.min + (p.max - p.min) * 0.37);
        for (double v : values) {
            Settings s = defaultSettings();
            if (p.type == Param::Type::Int || p.type == Param::Type::Enum || p.type == Param::Type::Bool)
                v = std::floor(v);
            p.set(s, v);
            Settings back = defaultSettings();
            applyJson(back, nlohmann::json::parse(toJson(s).dump()), "roundtrip");
            EXPECT_TRUE(back == s) << p.key << "=" << v;
            // and through the --set text form
            Settings viaSet = defaultSettings();
            setParam(viaSet, p.key, p.format(p.get(s)));
            EXPECT_EQ(p.get(viaSet), p.get(s)) << p.key;
        }
    }
}

TEST(ParamSet, ParsesEveryType) {
    Settings s = defaultSettings();
    applyAssignment(s, "ao.radius=0.8");
    applyAssignment(s, "kernel.shape=sphere");
    applyAssignment(s, "kernel.separable=true");
    applyAssignment(s, "kernel.samples=200");
    applyAssignment(s, "denoise.kind=gaussian");
    applyAssignment(s, "ao.radius_mode=screen");
    EXPECT_FLOAT_EQ(s.ao.radius, 0.8f);
    EXPECT_EQ(s.kernel.shape, KernelShape::Sphere);
    EXPECT_TRUE(s.kernel.separable);
    EXPECT_EQ(s.kernel.samples, 200);
    EXPECT_EQ(s.denoise.kind, DenoiseKind::Gaussian);
    EXPECT_EQ(s.ao.radiusMode, RadiusMode::Screen);
}

TEST(ParamSet, ErrorsNameTheKeyAndTheProblem) {
    Settings s = defaultSettings();
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ao.radiuss=1"); }).find("unknown parameter 'ao.radiuss'"),
              std::string::npos);
    EXPECT_NE(
        errorOf([&] { applyAssignment(s, "ao.radius=-1"); }).find("ao.radius: value -1 is out of range"),
        std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ao.radius=abc"); }).find("ao.radius: 'abc' is not a number"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ao.radius=nan"); }).find("ao.radius"), std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ao.radius=inf"); }).find("ao.radius"), std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "kernel.samples=0"); }).find("kernel.samples"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "kernel.samples=257"); }).find("out of range [1, 256]"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "kernel.samples=2.5"); }).find("not an integer"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "kernel.shape=cube"); }).find("hemisphere|sphere"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "kernel.separable=maybe"); }).find("not a boolean"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "radius"); }).find("expected key=value"), std::string::npos);
    EXPECT_TRUE(s == defaultSettings()); // failed assignments leave settings untouched
}

TEST(Presets, BadFilesGiveOneClearError) {
    EXPECT_NE(errorOf([] { loadPreset("/nonexistent/p.json"); }).find("preset file not found"),
              std::string::npos);
    auto bad = writeTemp("bad.json", "{ \"ao\": { \"radius\": 0.5, }");
    EXPECT_NE(errorOf([&] { loadPreset(bad); }).find("is not valid JSON"), std::string::npos);
    auto unknown = writeTemp("unknown.json", R"({"ao": {"radios": 0.5}})");
    EXPECT_NE(errorOf([&] { loadPreset(unknown); }).find("unknown key 'ao.radios'"), std::string::npos);
    auto group = writeTemp("group.json", R"({"oa": {"radius": 0.5}})");
    EXPECT_NE(errorOf([&] { loadPreset(group); }).find("unknown key 'oa.radius'"), std::string::npos);
    auto neg = writeTemp("neg.json", R"({"ao": {"radius": -2}})");
    EXPECT_NE(errorOf([&] { loadPreset(neg); }).find("ao.radius: value -2 is out of range"),
              std::string::npos);
    auto type = writeTemp("type.json", R"({"kernel": {"samples": "many"}})");
    EXPECT_NE(errorOf([&] { loadPreset(type); }).find("kernel.samples: expected a number"),
              std::string::npos);
    auto arr = writeTemp("arr.json", R"([1,2])");
    EXPECT_NE(errorOf([&] { loadPreset(arr); }).find("must be a JSON object"), std::string::npos);
}

TEST(Presets, ShippedSeedPresetsReproduceTheArticles) {
    const std::string dir = std::string(SSAOLAB_ASSET_DIR) + "/presets/";
    Settings lo = loadPreset(dir + "learnopengl.json");
    EXPECT_EQ(lo.kernel.shape, KernelShape::Hemisphere);
    EXPECT_EQ(lo.kernel.samples, 64);
    EXPECT_EQ(lo.ao.radiusMode, RadiusMode::World); // the article's 0.5 scene units
    EXPECT_FLOAT_EQ(lo.ao.radius, 0.5f);
    EXPECT_FLOAT_EQ(lo.kernel.bias * lo.ao.radius, 0.025f); // its bias 0.025, as a fraction of the radius
    EXPECT_EQ(lo.kernel.rangeCheck, RangeCheck::Smoothstep);
    EXPECT_EQ(lo.kernel.noise, Noise::Tex4x4);
    EXPECT_EQ(lo.denoise.kind, DenoiseKind::Box4);

    Settings cs = loadPreset(dir + "crytek-sphere.json");
    EXPECT_EQ(cs.kernel.shape, KernelShape::Sphere);

    Settings s3 = loadPreset(dir + "seed003.json");
    EXPECT_EQ(s3.kernel.rangeCheck, RangeCheck::Hard);
    EXPECT_EQ(s3.kernel.depthTest, DepthTest::Fragment);
    EXPECT_EQ(s3.gbuffer.normalFormat, TargetFormat::RGBA8);
    EXPECT_EQ(s3.denoise.kind, DenoiseKind::Gaussian);
    EXPECT_EQ(s3.denoise.halfWidth, 2); // 5x5

    Settings s3s = loadPreset(dir + "seed003-separable.json");
    EXPECT_TRUE(s3s.kernel.separable);
    EXPECT_EQ(s3s.kernel.samples, 64); // N in both loops, not the article's 9

    Settings s1 = loadPreset(dir + "seed001.json");
    EXPECT_EQ(s1.kernel.positionSource, PositionSource::Depth);

    for (auto& e : std::filesystem::directory_iterator(dir)) {
        EXPECT_NO_THROW(loadPreset(e.path().string())) << e.path();
        EXPECT_TRUE(readPresetFile(e.path().string()).fixesRadius())
            << e.path() << ": seed presets keep their radius";
    }
}

TEST(ParamTable, EnumChoicesMapByNameToDistinctValues) {
    for (const auto& p : paramTable()) {
        if (p.type != Param::Type::Enum) continue;
        std::set<std::string> seen;
        for (const auto& choice : p.choices) {
            Settings s = defaultSettings();
            setParam(s, p.key, choice);
            EXPECT_EQ(p.format(p.get(s)), choice) << p.key; // the name reads back as itself
            seen.insert(toJson(s).dump());
        }
        EXPECT_EQ(seen.size(), p.choices.size()) << p.key << ": two names set the same value";
    }
}

TEST(ParamTable, DefaultsComeFromTheSettingsStruct) {
    const Settings d{};
    for (const auto& p : paramTable()) {
        EXPECT_EQ(p.def, p.get(d)) << p.key;
        EXPECT_TRUE(p.isDefault(d)) << p.key;
    }
    // The radius follows the scene by default, at a few percent of its size.
    EXPECT_EQ(d.ao.radiusMode, RadiusMode::Scene);
    EXPECT_GT(d.ao.radiusScene, 0.0f);
    EXPECT_LE(d.ao.radiusScene, 0.05f);
}

TEST(ParamTable, RowsDeclareWhenTheyApply) {
    Settings s = defaultSettings();
    const Param& sigma = *findParam("denoise.sigma");
    s.denoise.kind = DenoiseKind::Box4;
    EXPECT_FALSE(sigma.applies(s)); // sigma under box4 has no effect: greyed out
    s.denoise.kind = DenoiseKind::Gaussian;
    EXPECT_TRUE(sigma.applies(s));
    EXPECT_EQ(sigma.whenText(), "denoise.kind = gaussian|bilateral");
    EXPECT_FALSE(findParam("denoise.sharpness")->applies(s)); // the bilateral's own rows
    s.denoise.kind = DenoiseKind::Bilateral;
    EXPECT_TRUE(sigma.applies(s));
    EXPECT_TRUE(findParam("denoise.sharpness")->applies(s));
    for (const char* mode : {"world", "scene", "screen"}) {
        setParam(s, "ao.radius_mode", mode);
        int applying = 0;
        for (const char* k : {"ao.radius", "ao.radius_scene", "ao.radius_px"})
            applying += findParam(k)->applies(s);
        EXPECT_EQ(applying, 1) << mode; // exactly the radius of the chosen unit
    }
    // Every technique row applies only while its technique is chosen.
    for (const auto& p : paramTable())
        if (p.group() == "kernel" || p.group() == "gtao") {
            ASSERT_FALSE(p.when.empty()) << p.key;
            EXPECT_EQ(p.when.front().key, "ao.technique") << p.key;
        }
    EXPECT_TRUE(findParam("kernel.samples")->applies(defaultSettings()));
}

TEST(Presets, SceneSizeAndKeysAreRead) {
    auto path =
        writeTemp("with_scene.json",
                  R"({"scene": "sub/model.gltf", "size": [320, 200], "ao": {"radius_mode": "world"}})");
    Preset p = readPresetFile(path);
    ASSERT_TRUE(p.scene.has_value());
    EXPECT_EQ(*p.scene,
              (std::filesystem::path(SSAOLAB_TEST_TMP) / "sub/model.gltf").lexically_normal().string())
        << "a relative scene is relative to the preset file";
    ASSERT_TRUE(p.size.has_value());
    EXPECT_EQ(p.size->first, 320);
    EXPECT_TRUE(p.fixesRadius());
    EXPECT_FALSE(readPresetFile(writeTemp("no_radius.json", R"({"kernel": {"samples": 8}})")).fixesRadius());
    EXPECT_EQ(*readPresetFile(writeTemp("builtin.json", R"({"scene": "builtin:corner"})")).scene,
              "builtin:corner");
    EXPECT_NE(
        errorOf([] { readPresetFile(writeTemp("bad_size.json", R"({"size": [0, 10]})")); }).find("size"),
        std::string::npos);
    EXPECT_NE(errorOf([] { readPresetFile(writeTemp("bad_scene.json", R"({"scene": 3})")); }).find("scene"),
              std::string::npos);
    Preset round = presetFromJson(presetToJson(p), "round trip");
    EXPECT_EQ(round.scene, p.scene);
    EXPECT_EQ(round.size, p.size);
}

TEST(Params, AutoDenoiseIsEachTechniquesOwnChoiceAndAnExplicitKindStays) {
    Settings s = defaultSettings();
    ASSERT_EQ(s.denoise.kind, DenoiseKind::Auto);
    // Each technique's own choice, measured on the denoiser sweep (TechniqueInfo::denoiser in
    // techniques/*/technique.cpp), and never auto again.
    for (const auto& t : techniques()) {
        s.ao.technique = t.id;
        EXPECT_EQ(effectiveDenoise(s).kind, t.denoiser.kind) << t.id;
        EXPECT_NE(effectiveDenoise(s).kind, DenoiseKind::Auto) << t.id;
    }
    s.ao.technique = "kernel";
    EXPECT_EQ(effectiveDenoise(s).passes, 1);
    setParam(s, "denoise.kind", "box4");
    EXPECT_EQ(effectiveDenoise(s).kind, DenoiseKind::Box4);
    setParam(s, "denoise.kind", "auto");
    EXPECT_EQ(effectiveDenoise(s).kind, DenoiseKind::Bilateral);
}

// The quality levels and derived presets a technique declares (TechniqueInfo: what `make presets`
// tunes and rewrites, .ci/tune-presets.sh) are the shipped presets: each level's preset ID-LEVEL
// sets its rows, and each derived preset holds its technique's rows of the one it follows with its
// own rows over them.
TEST(Presets, EachTechniquesLevelsAndDerivedPresetsAreTheShippedOnes) {
    const std::string dir = std::string(SSAOLAB_ASSET_DIR) + "/presets/";
    auto rowsOf = [](const Settings& s, const std::string& group) {
        std::map<std::string, std::string> rows;
        for (const Param& p : paramTable())
            if (p.group() == group) rows[p.key] = p.format(p.get(s));
        return rows;
    };
    int levels = 0, derived = 0;
    for (const auto& t : techniques()) {
        EXPECT_TRUE(t.levels.empty() || !t.tuned.empty()) << t.id << ": levels with no row to tune";
        for (const auto& l : t.levels) {
            const std::string name = t.id + "-" + l.name;
            ASSERT_TRUE(std::filesystem::exists(dir + name + ".json")) << name << " (make presets)";
            const Settings s = loadPreset(dir + name + ".json");
            EXPECT_EQ(s.ao.technique, t.id) << name;
            Settings want = s;
            for (const auto& a : l.set)
                applyAssignment(want, a);
            EXPECT_EQ(rowsOf(s, t.id), rowsOf(want, t.id)) << name << " does not set its level's rows";
            ++levels;
        }
        for (const auto& d : t.derived) {
            Settings want = loadPreset(dir + d.from + ".json");
            for (const auto& a : d.set)
                applyAssignment(want, a);
            EXPECT_EQ(rowsOf(loadPreset(dir + d.name + ".json"), t.id), rowsOf(want, t.id)) << d.name;
            ++derived;
        }
    }
    EXPECT_GT(levels, 0);
    std::printf("%d quality levels and %d derived presets checked\n", levels, derived);
}

// The presets derived from the tuned ones (not tuned themselves) must follow them: `make presets`
// rewrites them after each fit (.ci/tune-presets.sh), and this catches a hand edit of one side.
TEST(Presets, DerivedPresetsFollowTheTunedLevelTheyComeFrom) {
    const std::string dir = std::string(SSAOLAB_ASSET_DIR) + "/presets/";
    auto read = [&](const std::string& name) {
        std::ifstream in(dir + name + ".json");
        EXPECT_TRUE(in.good()) << name;
        return nlohmann::json::parse(in);
    };
    for (const std::string level : {"low", "medium", "high", "ultra"}) {
        const auto full = read("vbao-" + level), half = read("vbao-half-" + level);
        EXPECT_EQ(half["vbao"], full["vbao"]) << level;
        EXPECT_EQ(half["ao"]["resolution"], "half") << level;
        auto ao = half["ao"];
        ao.erase("resolution");
        EXPECT_EQ(ao, full["ao"]) << level; // same technique, radius rule and power
        EXPECT_EQ(half["denoise"], full["denoise"]) << level;
    }
    const auto ultra = read("vbao-ultra"), max = read("vbao-max");
    auto rows = ultra["vbao"];
    rows["slices"] = 8;
    rows["steps"] = 24;
    EXPECT_EQ(max["vbao"], rows);
    EXPECT_EQ(max["ao"], ultra["ao"]);
    EXPECT_EQ(max["denoise"], ultra["denoise"]);
    const Settings s = loadPreset(dir + "vbao-max.json");
    EXPECT_EQ(s.vbao.slices, 8);
    EXPECT_EQ(s.vbao.steps, 24);
}
