// Settings → constants packing of the horizon techniques and the bilateral denoiser (pure): GTAO's
// quality presets and falloff arithmetic, SAO's normalisation. Ranges are the parameter table's
// (validateSettings): the packing trusts them, and the table refuses what it would have clamped.
#include "passes/denoise_weights.h"
#include "techniques/gtao/pack.h"
#include "techniques/hbao/pack.h"
#include "techniques/sao/pack.h"
#include "settings/params.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

TEST(GtaoPack, QualityPresetsAreXeGtaos) {
    GtaoSettings s;
    const std::pair<GtaoQuality, glm::ivec2> presets[] = {{GtaoQuality::Low, {1, 2}},
                                                          {GtaoQuality::Medium, {2, 2}},
                                                          {GtaoQuality::High, {3, 3}},
                                                          {GtaoQuality::Ultra, {9, 3}}};
    for (auto [q, ss] : presets) {
        s.quality = q;
        const auto c = packGtaoConstants(s, gpu::AoCommon{});
        EXPECT_EQ(c.modes.x, ss.x);
        EXPECT_EQ(c.modes.y, ss.y);
    }
    s.quality = GtaoQuality::Custom;
    s.slices = 5, s.steps = GTAO_MAX_STEPS;
    const auto c = packGtaoConstants(s, gpu::AoCommon{});
    EXPECT_EQ(c.modes.x, 5);
    EXPECT_EQ(c.modes.y, GTAO_MAX_STEPS);
}

TEST(GtaoPack, FalloffWeightIsOneInsideAndZeroAtTheSearchRadius) {
    GtaoSettings s;
    s.falloffRange = 0.4f;
    s.radiusMultiplier = 2.0f;
    const auto c = packGtaoConstants(s, gpu::AoCommon{});
    EXPECT_EQ(c.search.x, 2.0f);
    // weight(d) = saturate(d / R * mul + add), R the search radius: 1 at 0.6 R, 0 at R.
    auto weight = [&](float dOverR) { return std::clamp(dOverR * c.search.y + c.search.z, 0.0f, 1.0f); };
    EXPECT_NEAR(weight(0.6f), 1.0f, 1e-6f);
    EXPECT_NEAR(weight(0.8f), 0.5f, 1e-6f);
    EXPECT_NEAR(weight(1.0f), 0.0f, 1e-6f);
    EXPECT_EQ(weight(0.1f), 1.0f);
    EXPECT_GT(c.thin.y, 1.0f); // the first step is at least a pixel away
    s.falloffRange = 0.01f;     // the table's smallest: finite
    const auto d = packGtaoConstants(s, gpu::AoCommon{});
    EXPECT_TRUE(std::isfinite(d.search.y) && std::isfinite(d.search.z));
}

TEST(PackRanges, TheParameterTableRefusesWhatThePackingWouldHaveClamped) {
    // One check, by the table: a range the packing once clamped again (and a zero falloff it once
    // divided by) is refused by name before anything is packed.
    auto refused = [](void (*mutate)(Settings&), const char* key) {
        Settings s = defaultSettings();
        mutate(s);
        try {
            validateSettings(s);
        } catch (const Error& e) {
            return std::string(e.what()).find(key) != std::string::npos;
        }
        return false;
    };
    EXPECT_TRUE(refused([](Settings& s) { s.ao.technique = "gtao", s.gtao.falloffRange = 0.0f; }, "gtao.falloff_range"));
    EXPECT_TRUE(refused([](Settings& s) {
        s.ao.technique = "gtao", s.gtao.quality = GtaoQuality::Custom, s.gtao.steps = 1000;
    }, "gtao.steps"));
    EXPECT_TRUE(refused([](Settings& s) { s.ao.technique = "hbao", s.hbao.directions = 0; }, "hbao.directions"));
    EXPECT_TRUE(refused([](Settings& s) { s.ao.technique = "hbao", s.hbao.tangentBias = 2.0f; }, "hbao.tangent_bias"));
    EXPECT_TRUE(refused([](Settings& s) { s.ao.technique = "sao", s.sao.samples = 0; }, "sao.samples"));
    EXPECT_TRUE(refused([](Settings& s) { s.ao.technique = "sao", s.sao.intensity = -1.0f; }, "sao.intensity"));
    EXPECT_TRUE(refused([](Settings& s) { s.kernel.samples = 257; }, "kernel.samples"));
    EXPECT_TRUE(refused([](Settings& s) { s.denoise.kind = DenoiseKind::Bilateral, s.denoise.sigma = 0.0f; }, "denoise.sigma"));
    EXPECT_TRUE(refused([](Settings& s) { s.ao.power = std::nanf(""); }, "ao.power"));
    // A row that does not apply is not judged: a GTAO value means nothing to the kernel.
    Settings k = defaultSettings();
    k.gtao.falloffRange = 0.0f;
    EXPECT_NO_THROW(validateSettings(k));
    EXPECT_NO_THROW(validateSettings(defaultSettings()));
}

TEST(BilateralPack, WindowSigmaSharpnessAndFlags) {
    DenoiseSettings d;
    d.kind = DenoiseKind::Bilateral;
    d.halfWidth = 30; // the 2-D window is clamped: (2*30+1)^2 taps would stall a frame
    d.sigma = 2.0f;
    d.sharpness = 20.0f;
    const auto c = packBilateralConstants(d, true);
    EXPECT_EQ(c.taps.x, SSAO_BILATERAL_MAX_HALF_WIDTH);
    EXPECT_EQ(c.taps.z, SSAO_DENOISE_NORMAL_UNORM);
    EXPECT_EQ(c.offsetsWeights[0].x, 2.0f);
    EXPECT_EQ(c.offsetsWeights[0].y, 20.0f);
    EXPECT_GT(c.offsetsWeights[0].z, 1.0f); // a normal term that separates creases
    EXPECT_EQ(packBilateralConstants(d, false).taps.z, 0);
    // At full-resolution output taps.y is 0; at the AO's resolution it is the G-buffer's ratio k.
    EXPECT_EQ(c.taps.y, 0);
    EXPECT_EQ(packBilateralConstants(d, false, 2).taps.y, 2);
    EXPECT_EQ(packBilateralConstants(d, false, 4).taps.y, 4);
}

TEST(DenoisePack, JointUpsampleTakesTheFourCornersWithAOnePercentDepthTolerance) {
    const auto c = packJointUpsampleConstants();
    EXPECT_EQ(c.taps.x, 4);
    EXPECT_EQ(c.taps.w, 10); // thousandths of the depth
}

TEST(HbaoPack, CountsAndBias) {
    HbaoSettings s;
    s.directions = 6, s.steps = 5, s.tangentBias = 0.2f, s.maxRadiusPx = 64.0f;
    const auto c = packHbaoConstants(s, gpu::AoCommon{});
    EXPECT_EQ(c.modes.x, 6);
    EXPECT_EQ(c.modes.y, 5);
    EXPECT_FLOAT_EQ(c.params.x, 0.2f);
    EXPECT_FLOAT_EQ(c.params.y, 64.0f);
}

TEST(SaoPack, AlchemyNormalisation) {
    SaoSettings s;
    s.samples = 10, s.intensity = 1.5f, s.bias = 0.02f, s.turns = 7.0f;
    const auto c = packSaoConstants(s, gpu::AoCommon{});
    EXPECT_EQ(c.modes.x, 10);
    EXPECT_FLOAT_EQ(c.params.y, 2.0f * 1.5f / 10.0f); // 2 sigma / N
    EXPECT_FLOAT_EQ(c.params.z, 0.02f);
    EXPECT_GT(c.params.w, 0.0f); // epsilon: a tap at the pixel itself stays finite
}
