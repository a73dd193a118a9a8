#include "settings/params.h"
#include "ssao/constants.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

TEST(PackSsao, ModesFlagsAndParameters) {
    Settings s = defaultSettings();
    s.ssao.samples = 17;
    s.ssao.radius = 0.8f;
    s.ssao.bias = 0.05f;
    s.ssao.power = 2.0f;
    s.ssao.rangeCheck = RangeCheck::Hard;
    s.ssao.depthTest = DepthTest::Fragment;
    s.ssao.positionSource = PositionSource::Depth;
    s.ssao.noise = Noise::None;
    s.gbuffer.normalFormat = TargetFormat::RGBA8;
    auto c = packSsaoConstants(s.ssao, s.gbuffer, 640, 360);
    EXPECT_EQ(c.modes.x, 17);
    EXPECT_EQ(c.modes.y, SSAO_RANGE_HARD);
    EXPECT_EQ(c.modes.z, SSAO_DEPTHTEST_FRAGMENT);
    EXPECT_EQ(c.modes.w, SSAO_FLAG_POS_FROM_DEPTH | SSAO_FLAG_NORMAL_UNORM);
    EXPECT_FLOAT_EQ(c.params0.x, 0.8f);
    EXPECT_FLOAT_EQ(c.params0.y, 0.05f);
    EXPECT_FLOAT_EQ(c.params0.z, 2.0f);
    EXPECT_GT(c.params0.w, 0.0f);            // range-check epsilon: |dz| = 0 never divides by zero
    EXPECT_FLOAT_EQ(c.noiseScale.x, 160.0f); // screen / 4: one noise tile per 4x4 pixels
    EXPECT_FLOAT_EQ(c.noiseScale.y, 90.0f);
    for (int i = 0; i < 17; ++i)
        EXPECT_GT(glm::length(glm::vec3(c.kernel[i])), 0.0f);
    for (int i = 17; i < 2 * SSAO_MAX_SAMPLES; ++i)
        EXPECT_EQ(c.kernel[i], glm::vec4(0.0f)) << i;
}

TEST(PackSsao, SeparableFillsTwoPlaneSets) {
    Settings s = defaultSettings();
    s.ssao.separable = true;
    s.ssao.samples = 64;
    auto c = packSsaoConstants(s.ssao, s.gbuffer, 64, 64);
    EXPECT_TRUE(c.modes.w & SSAO_FLAG_SEPARABLE);
    for (int i = 0; i < 64; ++i) {
        EXPECT_EQ(c.kernel[i].y, 0.0f);
        EXPECT_EQ(c.kernel[SSAO_MAX_SAMPLES + i].x, 0.0f);
        EXPECT_GT(glm::length(glm::vec3(c.kernel[SSAO_MAX_SAMPLES + i])), 0.0f); // all N, not 9
    }
}

TEST(PackSsao, SampleCountClampedToTheArray) {
    Settings s = defaultSettings();
    s.ssao.samples = 256;
    EXPECT_EQ(packSsaoConstants(s.ssao, s.gbuffer, 8, 8).modes.x, 256);
}

TEST(PackBlur, BoxIsTheSeedsFourTapsMinusTwoToOne) {
    BlurSettings b;
    b.kind = BlurKind::Box4;
    auto c = packBlurConstants(b, 1);
    ASSERT_EQ(c.taps.x, 4);
    EXPECT_EQ(c.taps.y, 1);
    for (int i = 0; i < 4; ++i) {
        EXPECT_FLOAT_EQ(c.offsetsWeights[i].x, float(i - 2));
        EXPECT_FLOAT_EQ(c.offsetsWeights[i].y, 0.25f);
    }
}

TEST(PackBlur, GaussianWeightsNormalisedSymmetricAndGaussian) {
    BlurSettings b;
    b.kind = BlurKind::Gaussian;
    b.radius = 3;
    b.sigma = 1.3f;
    b.spacing = 2.0f;
    auto c = packBlurConstants(b, 0);
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

TEST(PackBlur, NoneIsAnIdentityTap) {
    BlurSettings b;
    b.kind = BlurKind::None;
    auto c = packBlurConstants(b, 0);
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
