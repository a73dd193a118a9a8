// The shared noise of the horizon techniques: the blue-noise tile is a permutation with little
// low-frequency energy (what makes it blue), and the kinds are packed where the shaders read them.
#include "techniques/noise/blue_noise.h"
#include "techniques/noise/noise.h"
#include "passes/position_pyramid_pass.h"
#include "renderer.h"
#include "settings/params.h"
#include "techniques/ao_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace ssao;

namespace {
// Variance of the means of 4x4 blocks (toroidal, every offset) of values v (n x n): the energy
// left after a small blur, i.e. the low-frequency content that a denoiser cannot remove.
double blockMeanVariance(const std::vector<double>& v, int n) {
    double sum = 0, sum2 = 0;
    int count = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double m = 0;
            for (int dy = 0; dy < 4; ++dy)
                for (int dx = 0; dx < 4; ++dx)
                    m += v[size_t(((y + dy) % n) * n + (x + dx) % n)];
            m /= 16.0;
            sum += m, sum2 += m * m, ++count;
        }
    const double mean = sum / count;
    return sum2 / count - mean * mean;
}
} // namespace

TEST(BlueNoise, VoidAndClusterIsAPermutationWithLittleLowFrequencyEnergy) {
    const int n = 32;
    const std::vector<uint32_t> r = voidAndCluster(n, 7u);
    ASSERT_EQ(r.size(), size_t(n * n));
    std::vector<uint32_t> sorted = r;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i)
        ASSERT_EQ(sorted[i], uint32_t(i)); // every rank once: a uniform histogram
    EXPECT_EQ(r, voidAndCluster(n, 7u));   // deterministic
    std::vector<double> blue(r.begin(), r.end()), white(blue);
    std::shuffle(white.begin(), white.end(), std::mt19937(3));
    const double vb = blockMeanVariance(blue, n), vw = blockMeanVariance(white, n);
    std::printf("4x4 block-mean variance: blue %.1f, white %.1f (ratio %.3f)\n", vb, vw, vb / vw);
    EXPECT_LT(vb, 0.2 * vw);
}

TEST(BlueNoise, TheShadersTextureHasTwoChannelsInTheOpenUnitInterval) {
    const std::vector<float>& t = blueNoise64Rg();
    ASSERT_EQ(t.size(), size_t(kBlueNoiseSize * kBlueNoiseSize * 2));
    double mean[2] = {0, 0};
    for (size_t i = 0; i < t.size(); ++i) {
        ASSERT_GT(t[i], 0.0f);
        ASSERT_LT(t[i], 1.0f);
        mean[i % 2] += t[i];
    }
    EXPECT_NEAR(mean[0] / (t.size() / 2), 0.5, 1e-6);
    EXPECT_NEAR(mean[1] / (t.size() / 2), 0.5, 1e-6);
    EXPECT_NE(t[0], t[1]); // independent patterns
}

TEST(NoisePack, KindsPyramidAndBindingsGoWhereTheShadersAndTheCpuReadThem) {
    // The shared block gets the technique's noise kind and pyramid offset (one place for all
    // techniques); the CPU's choices (the blue tile, the pyramid) come from the settings, not from
    // the packed words.
    Settings s = defaultSettings();
    s.ao.technique = "vbao";
    s.vbao.noise = AoNoise::Blue;
    s.vbao.pyramid = true;
    s.gbuffer.normalFormat = TargetFormat::RGBA8;
    Camera cam;
    FrameInfo f;
    f.camera = &cam;
    f.width = 64, f.height = 32;
    f.constants = packFrameConstants(cam, 64, 32, 1.0f);
    gpu::AoCommon c = aoCommonFor(s, f, s.vbao.noise, kXeGtaoMipOffset);
    EXPECT_EQ(int(c.estimator.y), SSAO_NOISE_BLUE);
    EXPECT_FLOAT_EQ(c.estimator.w, kXeGtaoMipOffset); // taps read MIP log2(d) - 3.3
    EXPECT_EQ(c.flags.z, 1.0f);                       // normals stored as (n+1)/2
    EXPECT_EQ(c.target.x, 64.0f);
    AoBindings b = aoBindings(s, s.vbao.noise, true);
    EXPECT_TRUE(b.blueNoise && b.pyramid && b.gbufferNormals);
    s.vbao.noise = AoNoise::None;
    s.ao.normals = NormalSource::Depth;
    s.ao.resolution = AoResolution::Half;
    c = aoCommonFor(s, f, s.vbao.noise, 0.0f);
    EXPECT_EQ(int(c.estimator.y), SSAO_NOISE_NONE);
    EXPECT_EQ(c.estimator.w, 0.0f);
    EXPECT_EQ(c.target.x, 32.0f); // the AO target at half resolution
    b = aoBindings(s, s.vbao.noise, false);
    EXPECT_FALSE(b.blueNoise || b.pyramid || b.gbufferNormals);
    // Every row choice maps to its SSAO_NOISE_* value.
    const auto choices = aoNoiseChoices();
    ASSERT_EQ(choices.size(), 5u);
    for (const auto& [name, kind] : choices) {
        gpu::AoCommon k{};
        packNoise(k, kind);
        EXPECT_EQ(int(k.estimator.y), int(kind)) << name;
    }
}
