#include "settings/params.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

using namespace ssao;
using ssaotest::writeTemp;

namespace {
std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
} // namespace

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
    for (const char* k :
         {"ssao.kernel", "ssao.separable", "ssao.samples", "ssao.radius", "ssao.bias", "ssao.range_check",
          "ssao.power", "ssao.noise", "ssao.seed", "ssao.position_source", "blur.kind", "blur.sigma",
          "blur.spacing", "gbuffer.position_format", "gbuffer.normal_format"})
        EXPECT_NE(findParam(k), nullptr) << k;
    EXPECT_EQ(findParam("ssao.samples")->max, 256.0); // not capped at 64
}

TEST(ParamTable, DefaultsRoundTripThroughJson) {
    Settings d = defaultSettings();
    Settings back = defaultSettings();
    back.ssao.radius = 9.0f; // make sure applyJson really writes
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
    applyAssignment(s, "ssao.radius=0.8");
    applyAssignment(s, "ssao.kernel=sphere");
    applyAssignment(s, "ssao.separable=true");
    applyAssignment(s, "ssao.samples=200");
    applyAssignment(s, "blur.kind=gaussian");
    EXPECT_FLOAT_EQ(s.ssao.radius, 0.8f);
    EXPECT_EQ(s.ssao.kernel, Kernel::Sphere);
    EXPECT_TRUE(s.ssao.separable);
    EXPECT_EQ(s.ssao.samples, 200);
    EXPECT_EQ(s.blur.kind, BlurKind::Gaussian);
}

TEST(ParamSet, ErrorsNameTheKeyAndTheProblem) {
    Settings s = defaultSettings();
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.radiuss=1"); }).find("unknown parameter 'ssao.radiuss'"),
              std::string::npos);
    EXPECT_NE(
        errorOf([&] { applyAssignment(s, "ssao.radius=-1"); }).find("ssao.radius: value -1 is out of range"),
        std::string::npos);
    EXPECT_NE(
        errorOf([&] { applyAssignment(s, "ssao.radius=abc"); }).find("ssao.radius: 'abc' is not a number"),
        std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.radius=nan"); }).find("ssao.radius"), std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.radius=inf"); }).find("ssao.radius"), std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.samples=0"); }).find("ssao.samples"), std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.samples=257"); }).find("out of range [1, 256]"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.samples=2.5"); }).find("not an integer"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.kernel=cube"); }).find("hemisphere|sphere"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "ssao.separable=maybe"); }).find("not a boolean"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { applyAssignment(s, "radius"); }).find("expected key=value"), std::string::npos);
    EXPECT_TRUE(s == defaultSettings()); // failed assignments leave settings untouched
}

TEST(Presets, BadFilesGiveOneClearError) {
    EXPECT_NE(errorOf([] { loadPreset("/nonexistent/p.json"); }).find("preset file not found"),
              std::string::npos);
    auto bad = writeTemp("bad.json", "{ \"ssao\": { \"radius\": 0.5, }");
    EXPECT_NE(errorOf([&] { loadPreset(bad); }).find("is not valid JSON"), std::string::npos);
    auto unknown = writeTemp("unknown.json", R"({"ssao": {"radios": 0.5}})");
    EXPECT_NE(errorOf([&] { loadPreset(unknown); }).find("unknown key 'ssao.radios'"), std::string::npos);
    auto group = writeTemp("group.json", R"({"ssoa": {"radius": 0.5}})");
    EXPECT_NE(errorOf([&] { loadPreset(group); }).find("unknown key 'ssoa.radius'"), std::string::npos);
    auto neg = writeTemp("neg.json", R"({"ssao": {"radius": -2}})");
    EXPECT_NE(errorOf([&] { loadPreset(neg); }).find("ssao.radius: value -2 is out of range"),
              std::string::npos);
    auto type = writeTemp("type.json", R"({"ssao": {"samples": "many"}})");
    EXPECT_NE(errorOf([&] { loadPreset(type); }).find("ssao.samples: expected a number"), std::string::npos);
    auto arr = writeTemp("arr.json", R"([1,2])");
    EXPECT_NE(errorOf([&] { loadPreset(arr); }).find("must be a JSON object"), std::string::npos);
}

TEST(Presets, ShippedSeedPresetsReproduceTheArticles) {
    const std::string dir = std::string(SSAOLAB_ASSET_DIR) + "/presets/";
    Settings lo = loadPreset(dir + "learnopengl.json");
    EXPECT_EQ(lo.ssao.kernel, Kernel::Hemisphere);
    EXPECT_EQ(lo.ssao.samples, 64);
    EXPECT_FLOAT_EQ(lo.ssao.radius, 0.5f);
    EXPECT_FLOAT_EQ(lo.ssao.bias, 0.025f);
    EXPECT_EQ(lo.ssao.rangeCheck, RangeCheck::Smoothstep);
    EXPECT_EQ(lo.ssao.noise, Noise::Tex4x4);
    EXPECT_EQ(lo.blur.kind, BlurKind::Box4);

    Settings cs = loadPreset(dir + "crytek-sphere.json");
    EXPECT_EQ(cs.ssao.kernel, Kernel::Sphere);

    Settings s3 = loadPreset(dir + "seed003.json");
    EXPECT_EQ(s3.ssao.rangeCheck, RangeCheck::Hard);
    EXPECT_EQ(s3.ssao.depthTest, DepthTest::Fragment);
    EXPECT_EQ(s3.gbuffer.normalFormat, TargetFormat::RGBA8);
    EXPECT_EQ(s3.blur.kind, BlurKind::Gaussian);
    EXPECT_EQ(s3.blur.radius, 2); // 5x5

    Settings s3s = loadPreset(dir + "seed003-separable.json");
    EXPECT_TRUE(s3s.ssao.separable);
    EXPECT_EQ(s3s.ssao.samples, 64); // N in both loops, not the article's 9

    Settings s1 = loadPreset(dir + "seed001.json");
    EXPECT_EQ(s1.ssao.positionSource, PositionSource::Depth);

    for (auto& e : std::filesystem::directory_iterator(dir))
        EXPECT_NO_THROW(loadPreset(e.path().string())) << e.path();
}
