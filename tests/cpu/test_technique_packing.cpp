// Settings → constants packing of the horizon techniques and the bilateral denoiser (pure): GTAO's
// quality presets and falloff arithmetic, HBAO's limits, flags.
#include "passes/denoise_weights.h"
#include "techniques/gtao/pack.h"
#include "techniques/hbao/pack.h"
#include "techniques/sao/pack.h"

#include <gtest/gtest.h>

using namespace ssao;

TEST(GtaoPack, QualityPresetsAreXeGtaos) {
    GtaoSettings s;
    const std::pair<GtaoQuality, glm::ivec2> presets[] = {{GtaoQuality::Low, {1, 2}},
                                                          {GtaoQuality::Medium, {2, 2}},
                                                          {GtaoQuality::High, {3, 3}},
                                                          {GtaoQuality::Ultra, {9, 3}}};
    for (auto [q, ss] : presets) {
        s.quality = q;
        const auto c = packGtaoConstants(s, gpu::AoCommon{}, false);
        EXPECT_EQ(c.modes.x, ss.x);
        EXPECT_EQ(c.modes.y, ss.y);
    }
    s.quality = GtaoQuality::Custom;
    s.slices = 5, s.steps = 1000; // clamped to the shader's limits
    const auto c = packGtaoConstants(s, gpu::AoCommon{}, false);
    EXPECT_EQ(c.modes.x, 5);
    EXPECT_EQ(c.modes.y, GTAO_MAX_STEPS);
}

TEST(GtaoPack, FalloffWeightIsOneInsideAndZeroAtTheSearchRadius) {
    GtaoSettings s;
    s.falloffRange = 0.4f;
    s.radiusMultiplier = 2.0f;
    const auto c = packGtaoConstants(s, gpu::AoCommon{}, true);
    EXPECT_EQ(c.params.x, 2.0f);
    // weight(d) = saturate(d / R * mul + add), R the search radius: 1 at 0.6 R, 0 at R.
    auto weight = [&](float dOverR) { return std::clamp(dOverR * c.params.y + c.params.z, 0.0f, 1.0f); };
    EXPECT_NEAR(weight(0.6f), 1.0f, 1e-6f);
    EXPECT_NEAR(weight(0.8f), 0.5f, 1e-6f);
    EXPECT_NEAR(weight(1.0f), 0.0f, 1e-6f);
    EXPECT_EQ(weight(0.1f), 1.0f);
    EXPECT_EQ(c.modes.z, GTAO_FLAG_NOISE | GTAO_FLAG_NORMAL_UNORM);
    EXPECT_GT(c.params2.y, 1.0f); // the first step is at least a pixel away
    s.noise = GtaoNoise::None;
    s.falloffRange = 0.0f; // clamped: no division by zero
    const auto d = packGtaoConstants(s, gpu::AoCommon{}, false);
    EXPECT_TRUE(std::isfinite(d.params.y) && std::isfinite(d.params.z));
    EXPECT_EQ(d.modes.z, 0);
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
    d.sigma = 0.0f;                         // never a division by zero in exp(-d^2 / 2 sigma^2)
    EXPECT_GT(packBilateralConstants(d, false).offsetsWeights[0].x, 0.0f);
}

TEST(HbaoPack, CountsBiasAndLimitsAreClamped) {
    HbaoSettings s;
    s.directions = 0, s.steps = 1000, s.tangentBias = 2.0f, s.maxRadiusPx = 0.0f;
    const auto c = packHbaoConstants(s, gpu::AoCommon{}, true);
    EXPECT_EQ(c.modes.x, 1);              // at least one direction
    EXPECT_EQ(c.modes.y, HBAO_MAX_STEPS); // the shader's loop bound
    EXPECT_LT(c.params.x, 1.0f);          // bias < 1: the normaliser (1 - bias) stays positive
    EXPECT_GE(c.params.y, 2.0f);          // a radius of at least two pixels
    EXPECT_EQ(c.modes.z, HBAO_FLAG_NOISE | HBAO_FLAG_NORMAL_UNORM);
    s.noise = HbaoNoise::None;
    EXPECT_EQ(packHbaoConstants(s, gpu::AoCommon{}, false).modes.z, 0);
}

TEST(SaoPack, AlchemyNormalisationAndLimits) {
    SaoSettings s;
    s.samples = 10, s.intensity = 1.5f, s.bias = 0.02f, s.turns = 7.0f;
    const auto c = packSaoConstants(s, gpu::AoCommon{}, false);
    EXPECT_EQ(c.modes.x, 10);
    EXPECT_FLOAT_EQ(c.params.y, 2.0f * 1.5f / 10.0f); // 2 sigma / N
    EXPECT_FLOAT_EQ(c.params.z, 0.02f);
    EXPECT_GT(c.params.w, 0.0f); // epsilon: a tap at the pixel itself stays finite
    EXPECT_EQ(c.modes.y, SAO_FLAG_NOISE);
    s.samples = 0;
    s.intensity = -1.0f;
    const auto d = packSaoConstants(s, gpu::AoCommon{}, true);
    EXPECT_EQ(d.modes.x, 1);
    EXPECT_EQ(d.params.y, 0.0f);
    EXPECT_EQ(d.modes.y, SAO_FLAG_NOISE | SAO_FLAG_NORMAL_UNORM);
}
