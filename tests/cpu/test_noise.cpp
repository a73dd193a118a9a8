// The shared noise of the horizon techniques: the blue-noise tile is a permutation with little
// low-frequency energy (what makes it blue), and the kinds are packed where the shaders read them.
#include "techniques/noise/blue_noise.h"
#include "techniques/noise/noise.h"
#include "techniques/vbao/pack.h"

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

TEST(NoisePack, KindsPyramidAndFlagsGoWhereTheShadersReadThem) {
    VbaoSettings s;
    s.slices = 99, s.steps = -3; // clamped to the shader's limits
    s.thickness = -1.0f;         // no negative depth
    s.noise = AoNoise::Blue;
    s.pyramid = true;
    auto c = packVbaoConstants(s, gpu::AoCommon{}, true);
    EXPECT_EQ(c.modes.x, VBAO_MAX_SLICES);
    EXPECT_EQ(c.modes.y, 1);
    EXPECT_EQ(c.params.x, 0.0f);
    EXPECT_EQ(int(c.aoCommon.shape.y), SSAO_NOISE_BLUE);
    EXPECT_GT(c.aoCommon.shape.w, 0.0f); // the pyramid's MIP offset
    EXPECT_EQ(c.modes.z, VBAO_FLAG_NOISE | VBAO_FLAG_NORMAL_UNORM);
    s.noise = AoNoise::None;
    s.pyramid = false;
    c = packVbaoConstants(s, gpu::AoCommon{}, false);
    EXPECT_EQ(int(c.aoCommon.shape.y), SSAO_NOISE_NONE);
    EXPECT_EQ(c.aoCommon.shape.w, 0.0f);
    EXPECT_EQ(c.modes.z, 0);
    // Every row choice maps to its SSAO_NOISE_* value.
    const auto choices = aoNoiseChoices();
    ASSERT_EQ(choices.size(), 5u);
    for (const auto& [name, kind] : choices) {
        gpu::AoCommon k{};
        packNoise(k, kind);
        EXPECT_EQ(int(k.shape.y), int(kind)) << name;
    }
}
