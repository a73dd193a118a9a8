// Settings → GPU constants: the pure packing functions of every pass and of the kernel technique.
#include "passes/denoise_weights.h"
#include "renderer.h"
#include "settings/params.h"
#include "techniques/ao_common.h"
#include "techniques/ao_pass.h"
#include "techniques/kernel/pack.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

namespace {
gpu::AoCommon common(int w = 640, int h = 360) {
    return packAoCommon(Settings{}.ao, 10.0f, 0.002f, {w, h});
}
} // namespace

TEST(PackKernel, ModesFlagsAndParameters) {
    Settings s = defaultSettings();
    s.kernel.samples = 17;
    s.kernel.bias = 0.05f;
    s.kernel.rangeCheck = RangeCheck::Hard;
    s.kernel.depthTest = DepthTest::Fragment;
    s.kernel.positionSource = PositionSource::Depth;
    s.kernel.noise = Noise::None;
    s.kernel.ownTexel = OwnTexel::Test;
    auto c = packKernelConstants(s.kernel, common());
    EXPECT_EQ(c.modes.x, 17);
    EXPECT_EQ(c.modes.y, KERNEL_RANGE_HARD);
    EXPECT_EQ(c.modes.z, KERNEL_DEPTHTEST_FRAGMENT);
    EXPECT_EQ(c.modes.w, KERNEL_FLAG_POS_FROM_DEPTH);
    s.kernel.ownTexel = OwnTexel::Open;
    EXPECT_EQ(packKernelConstants(s.kernel, common()).modes.w, KERNEL_FLAG_POS_FROM_DEPTH | KERNEL_FLAG_OWN_TEXEL_OPEN);
    EXPECT_FLOAT_EQ(c.params.x, 0.05f);
    EXPECT_GT(c.params.y, 0.0f);             // range-check floor: |dz| = 0 never divides by zero
    EXPECT_FLOAT_EQ(c.noiseScale.x, 160.0f); // AO target / 4: one noise tile per 4x4 pixels
    EXPECT_FLOAT_EQ(c.noiseScale.y, 90.0f);
    for (int i = 0; i < 17; ++i)
        EXPECT_GT(glm::length(glm::vec3(c.kernel[i])), 0.0f);
    for (int i = 17; i < 2 * KERNEL_MAX_SAMPLES; ++i)
        EXPECT_EQ(c.kernel[i], glm::vec4(0.0f)) << i;
}

TEST(PackKernel, NoiseTilesFollowTheAoResolution) {
    auto c = packKernelConstants(Settings{}.kernel, common(320, 180)); // half of 640x360
    EXPECT_FLOAT_EQ(c.noiseScale.x, 80.0f);
    EXPECT_FLOAT_EQ(c.aoCommon.target.x, 320.0f);
}

TEST(PackKernel, SeparableFillsTwoPlaneSets) {
    Settings s = defaultSettings();
    s.kernel.separable = true;
    s.kernel.samples = 64;
    auto c = packKernelConstants(s.kernel, common());
    EXPECT_TRUE(c.modes.w & KERNEL_FLAG_SEPARABLE);
    for (int i = 0; i < 64; ++i) {
        EXPECT_EQ(c.kernel[i].y, 0.0f);
        EXPECT_EQ(c.kernel[KERNEL_MAX_SAMPLES + i].x, 0.0f);
        EXPECT_GT(glm::length(glm::vec3(c.kernel[KERNEL_MAX_SAMPLES + i])), 0.0f); // all N, not 9
    }
}

TEST(PackKernel, TheLargestSampleCountFillsTheArray) {
    Settings s = defaultSettings();
    s.kernel.samples = 256;
    EXPECT_EQ(packKernelConstants(s.kernel, common()).modes.x, 256);
}

TEST(AoCommon, RadiusInEachModeInWorldUnitsAndPixels) {
    AoSettings a;
    const float diag = 800.0f; // a millimetre model
    const float upp = 0.001f;  // 1 mm per pixel at unit depth
    a.radiusMode = RadiusMode::World;
    a.radius = 0.5f;
    EXPECT_FLOAT_EQ(worldRadius(a, diag, 1000.0f, upp), 0.5f);
    EXPECT_NEAR(radiusInPixels(a, diag, 1000.0f, upp), 0.5f, 1e-4f); // half a pixel: flat grey AO
    a.radiusMode = RadiusMode::Scene;
    a.radiusScene = 0.05f;
    EXPECT_FLOAT_EQ(worldRadius(a, diag, 1000.0f, upp), 40.0f); // follows the scene: 5 % of 800
    a.radiusMode = RadiusMode::Screen;
    a.radiusPx = 24.0f;
    EXPECT_FLOAT_EQ(worldRadius(a, diag, 1000.0f, upp), 24.0f);  // 24 px of 1 mm at depth 1000
    EXPECT_FLOAT_EQ(radiusInPixels(a, diag, 10.0f, upp), 24.0f); // the same pixels at every depth
    const auto c = packAoCommon(a, diag, upp, {64, 32});
    EXPECT_EQ(int(c.radius.z), SSAO_RADIUS_SCREEN);
    EXPECT_FLOAT_EQ(c.radius.y * c.radius.w * 1000.0f, 24.0f); // what the shader computes
    a.radiusMode = RadiusMode::Scene;
    EXPECT_FLOAT_EQ(packAoCommon(a, diag, upp, {64, 32}).radius.x, 40.0f);
    // The normal source is the shaders' SSAO_NORMALS_*; noise and pyramid are the technique's (none, off).
    EXPECT_EQ(int(packAoCommon(a, diag, upp, {64, 32}).estimator.z), SSAO_NORMALS_GBUFFER);
    a.normals = NormalSource::Depth;
    const auto d = packAoCommon(a, diag, upp, {64, 32});
    EXPECT_EQ(int(d.estimator.z), SSAO_NORMALS_DEPTH);
    EXPECT_EQ(int(d.estimator.y), SSAO_NOISE_NONE);
    EXPECT_EQ(d.estimator.w, 0.0f);
    // The G-buffer's normal encoding is shared too (flags.z), so no technique defines its own flag.
    EXPECT_EQ(d.flags.z, 0.0f);
    EXPECT_EQ(packAoCommon(a, diag, upp, {64, 32}, true, /*normalUnorm=*/true).flags.z, 1.0f);
}

// The AO shader variant follows the packed words it runs with, so an input the block enables is
// always compiled in and one it leaves off never is.
TEST(AoCommon, FeatureDefinesFollowThePackedBlock) {
    auto value = [](const gl::Defines& d, const char* name) -> std::string {
        for (const auto& [k, v] : d)
            if (k == name) return v;
        return "";
    };
    auto has = [&](const gl::Defines& d, const char* name) { return !value(d, name).empty(); };
    Settings s = defaultSettings();
    FrameInfo f;
    f.width = 64, f.height = 32;
    f.constants.proj = glm::perspective(1.0f, 2.0f, 0.1f, 10.0f);
    const gpu::AoCommon plain = aoCommonFor(s, f, AoNoise::Ign, 0.0f);
    const gl::Defines none = aoFeatureDefines(plain);
    EXPECT_FALSE(has(none, "AO_PYRAMID") || has(none, "AO_BAND") || has(none, "AO_BACK_DEPTH") ||
                 has(none, "AO_NORMALS_DEPTH"));
    EXPECT_EQ(value(none, "AO_NOISE"), std::to_string(int(plain.estimator.y))); // the packed kind
    EXPECT_EQ(value(none, "AO_NOISE"), std::to_string(SSAO_NOISE_IGN));
    EXPECT_EQ(value(aoFeatureDefines(aoCommonFor(s, f, AoNoise::Blue, 0.0f)), "AO_NOISE"),
              std::to_string(SSAO_NOISE_BLUE));
    EXPECT_EQ(has(none, "AO_POWER_ONE"), plain.estimator.x == 1.0f);
    EXPECT_TRUE(has(aoFeatureDefines(aoCommonFor(s, f, AoNoise::Ign, 3.3f)), "AO_PYRAMID"));
    s.ao.power = 2.0f;
    EXPECT_FALSE(has(aoFeatureDefines(aoCommonFor(s, f, AoNoise::Ign, 0.0f)), "AO_POWER_ONE"));
    s.ao.power = 1.0f;
    EXPECT_TRUE(has(aoFeatureDefines(aoCommonFor(s, f, AoNoise::Ign, 0.0f)), "AO_POWER_ONE"));
    s.gbuffer.guardBandPx = 16;
    s.gbuffer.backFaces = true;
    s.ao.normals = NormalSource::Depth;
    const gpu::AoCommon all = aoCommonFor(s, f, AoNoise::Ign, 0.0f);
    const gl::Defines d = aoFeatureDefines(all);
    EXPECT_TRUE(has(d, "AO_BAND"));
    EXPECT_TRUE(has(d, "AO_BACK_DEPTH"));
    EXPECT_TRUE(has(d, "AO_NORMALS_DEPTH"));
    EXPECT_FALSE(has(d, "AO_PYRAMID"));
    EXPECT_EQ(int(all.flags.w), SSAO_AO_BAND | SSAO_AO_BACK_DEPTH); // what the shader checks inside
}

TEST(AoCommon, UnitsPerPixelMatchTheFieldOfView) {
    const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 2.0f, 0.1f, 10.0f);
    // 90° vertical: the view at unit depth is 2 units tall, over 500 pixels.
    EXPECT_NEAR(unitsPerPixelAtUnitDepth(proj, 500), 2.0f / 500.0f, 1e-6f);
    EXPECT_FLOAT_EQ(resolutionScale(AoResolution::Half), 0.5f);
    EXPECT_FLOAT_EQ(resolutionScale(AoResolution::Quarter), 0.25f);
}

TEST(PackDenoise, BoxIsTheSeedsFourTapsMinusTwoToOne) {
    DenoiseSettings d;
    d.kind = DenoiseKind::Box4;
    auto c = packDenoiseConstants(d, 1);
    ASSERT_EQ(c.taps.x, 4);
    EXPECT_EQ(c.taps.y, 1);
    for (int i = 0; i < 4; ++i) {
        EXPECT_FLOAT_EQ(c.offsetsWeights[i].x, float(i - 2));
        EXPECT_FLOAT_EQ(c.offsetsWeights[i].y, 0.25f);
    }
}

TEST(PackDenoise, TheCentredBoxHasNoHalfPixelShift) {
    // The seed's taps -2..+1 average around -0.5 px: the blurred AO moves half a pixel per pass
    // (a pixel over x and y). The centred variant reads at -1.5..+1.5 between texels: mean 0.
    DenoiseSettings d;
    auto centre = [](const gpu::DenoiseConstants& c) {
        double m = 0;
        for (int i = 0; i < c.taps.x; ++i)
            m += c.offsetsWeights[i].x * c.offsetsWeights[i].y;
        return m;
    };
    d.kind = DenoiseKind::Box4;
    EXPECT_DOUBLE_EQ(centre(packDenoiseConstants(d, 0)), -0.5);
    d.kind = DenoiseKind::Box4Centred;
    const auto c = packDenoiseConstants(d, 0);
    ASSERT_EQ(c.taps.x, 4);
    EXPECT_DOUBLE_EQ(centre(c), 0.0);
    EXPECT_FLOAT_EQ(c.offsetsWeights[0].x, -1.5f);
    EXPECT_FLOAT_EQ(c.offsetsWeights[3].x, 1.5f);
}

TEST(PackDenoise, GaussianWeightsNormalisedSymmetricAndGaussian) {
    DenoiseSettings d;
    d.kind = DenoiseKind::Gaussian;
    d.halfWidth = 3;
    d.sigma = 1.3f;
    d.spacing = 2.0f;
    auto c = packDenoiseConstants(d, 0);
    ASSERT_EQ(c.taps.x, 7);
    float sum = 0;
    for (int i = 0; i < 7; ++i)
        sum += c.offsetsWeights[i].y;
    EXPECT_NEAR(sum, 1.0f, 1e-6f);
    for (int i = 0; i < 3; ++i)
        EXPECT_FLOAT_EQ(c.offsetsWeights[i].y, c.offsetsWeights[6 - i].y);
    EXPECT_FLOAT_EQ(c.offsetsWeights[0].x, -6.0f); // spacing 2 pixels
    EXPECT_NEAR(c.offsetsWeights[4].y / c.offsetsWeights[3].y, std::exp(-1.0f / (2 * 1.3f * 1.3f)), 1e-6f);
}

TEST(PackDenoise, NoneIsAnIdentityTap) {
    DenoiseSettings d;
    d.kind = DenoiseKind::None;
    auto c = packDenoiseConstants(d, 0);
    ASSERT_EQ(c.taps.x, 1);
    EXPECT_EQ(c.offsetsWeights[0], glm::vec4(0, 1, 0, 0));
}

TEST(PackFrame, MatricesAndViewport) {
    Camera cam{{1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 60.0f, 0.1f, 100.0f};
    auto f = packFrameConstants(cam, 800, 400, 5.0f);
    glm::mat4 id = f.invProj * f.proj;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(id[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
    EXPECT_EQ(f.viewport, glm::vec4(800, 400, 1.0f / 800, 1.0f / 400));
    EXPECT_EQ(f.clip, glm::vec4(0.1f, 100.0f, 5.0f, 0.0f));
    // The eye maps to the view-space origin; the target lies on -z.
    glm::vec4 t = f.view * glm::vec4(0, 0, 0, 1);
    EXPECT_NEAR(t.x, 0.0f, 1e-5f);
    EXPECT_NEAR(t.y, 0.0f, 1e-5f);
    EXPECT_NEAR(t.z, -std::sqrt(14.0f), 1e-5f);
}

TEST(PackDenoise, WeightsNeverSumAboveOneInFloat) {
    // A wide, narrow gaussian: 65 taps of which most are tiny. Summed in float (as the shader
    // does), the weights must not exceed 1, or an open pixel's AO becomes 1.0000001.
    for (int hw : {2, 7, 16, 32})
        for (float sigma : {0.1f, 0.7f, 1.5f, 4.0f, 32.0f}) {
            DenoiseSettings d;
            d.kind = DenoiseKind::Gaussian;
            d.halfWidth = hw;
            d.sigma = sigma;
            const auto c = packDenoiseConstants(d, 0);
            float total = 0.0f;
            for (int i = 0; i < c.taps.x; ++i)
                total += 1.0f * c.offsetsWeights[i].y;
            EXPECT_LE(total, 1.0f) << hw << " " << sigma;
            EXPECT_GT(total, 0.99999f) << hw << " " << sigma;
        }
}
