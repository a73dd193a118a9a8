#include "techniques/kernel/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

namespace {
const SampleSet kShapes[] = {SampleSet::Hemisphere, SampleSet::Sphere, SampleSet::PlaneXZ,
                             SampleSet::PlaneYZ};
}

TEST(Kernel, CountMatchesRequestForEveryShape) {
    for (SampleSet s : kShapes)
        for (int n : {1, 2, 9, 64, 256})
            EXPECT_EQ(makeKernel(s, n, 0).size(), size_t(n));
}

TEST(Kernel, EverySampleInsideUnitBallAndWithinItsScale) {
    for (SampleSet s : kShapes) {
        const int n = 256;
        auto k = makeKernel(s, n, 3);
        for (int i = 0; i < n; ++i) {
            float len = glm::length(k[size_t(i)]);
            EXPECT_LE(len, 1.0f);
            // lerp(0.1, 1, (i/N)^2) is the maximum length of sample i (times a uniform [0,1)).
            EXPECT_LE(len, kernelScale(i, n) + 1e-6f) << "sample " << i;
            EXPECT_TRUE(std::isfinite(len));
        }
    }
}

TEST(Kernel, HemisphereAndPlaneSetsStayAboveTheSurface) {
    for (SampleSet s : {SampleSet::Hemisphere, SampleSet::PlaneXZ, SampleSet::PlaneYZ})
        for (auto& v : makeKernel(s, 256, 11))
            EXPECT_GE(v.z, 0.0f);
    for (auto& v : makeKernel(SampleSet::PlaneXZ, 64, 1))
        EXPECT_EQ(v.y, 0.0f);
    for (auto& v : makeKernel(SampleSet::PlaneYZ, 64, 1))
        EXPECT_EQ(v.x, 0.0f);
}

TEST(Kernel, SphereKernelPutsAboutHalfTheSamplesBelowTheSurface) {
    int below = 0;
    auto k = makeKernel(SampleSet::Sphere, 256, 5);
    for (auto& v : k)
        below += v.z < 0.0f;
    EXPECT_GT(below, 256 * 0.38);
    EXPECT_LT(below, 256 * 0.62);
}

TEST(Kernel, DensityIncreasesTowardTheCentre) {
    // The lerp(0.1,1,s^2) scale exists to cluster samples near the pixel: the first quarter of
    // the kernel must be much shorter on average than the last quarter.
    auto k = makeKernel(SampleSet::Hemisphere, 256, 2);
    double first = 0, last = 0;
    for (int i = 0; i < 64; ++i) {
        first += glm::length(k[size_t(i)]);
        last += glm::length(k[size_t(192 + i)]);
    }
    EXPECT_LT(first / 64, 0.25 * last / 64);
    // And more than half of all samples lie within half the radius.
    int inner = 0;
    for (auto& v : k)
        inner += glm::length(v) < 0.5f;
    EXPECT_GT(inner, 128);
}

TEST(Kernel, DeterministicPerSeed) {
    auto a = makeKernel(SampleSet::Hemisphere, 64, 42), b = makeKernel(SampleSet::Hemisphere, 64, 42);
    auto c = makeKernel(SampleSet::Hemisphere, 64, 43);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(Noise, SixteenNonZeroVectorsInTheTangentPlane) {
    for (uint32_t seed : {0u, 1u, 99u}) {
        auto n = makeNoise(seed);
        ASSERT_EQ(n.size(), 16u);
        for (auto& v : n) {
            EXPECT_EQ(v.z, 0.0f);
            EXPECT_GE(v.x, -1.0f);
            EXPECT_LE(v.x, 1.0f);
            EXPECT_GE(v.y, -1.0f);
            EXPECT_LE(v.y, 1.0f);
            EXPECT_GT(glm::length(v), 1e-2f);
        }
    }
}

namespace {
void expectOrthonormal(const glm::mat3& m, const glm::vec3& n) {
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(std::isfinite(m[i].x) && std::isfinite(m[i].y) && std::isfinite(m[i].z));
        EXPECT_NEAR(glm::length(m[i]), 1.0f, 1e-4f);
        for (int j = i + 1; j < 3; ++j)
            EXPECT_NEAR(glm::dot(m[i], m[j]), 0.0f, 1e-4f);
    }
    EXPECT_NEAR(glm::length(m[2] - n), 0.0f, 1e-6f); // the third column is the normal itself
    EXPECT_GT(glm::determinant(m), 0.0f);            // right-handed: t x b = n
}
} // namespace

TEST(TangentFrame, OrthonormalForRandomInputs) {
    Rng rng(7);
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 n =
            glm::normalize(glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) + 1e-3f);
        glm::vec3 r(rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0f);
        expectOrthonormal(tangentFrame(n, r), n);
    }
}

TEST(TangentFrame, OrthonormalWhenTheRandomVectorIsDegenerate) {
    // Gram–Schmidt gives a zero tangent here; the seeds' normalize(0) would be NaN.
    const glm::vec3 normals[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                 {0, 0, 1}, {0, 0, -1}, glm::normalize(glm::vec3(1, 1, 0))};
    for (const auto& n : normals) {
        expectOrthonormal(tangentFrame(n, n), n);                          // r parallel to n
        expectOrthonormal(tangentFrame(n, -n * 0.3f), n);                  // r anti-parallel
        expectOrthonormal(tangentFrame(n, glm::vec3(0)), n);               // r zero
        expectOrthonormal(tangentFrame(n, n + glm::vec3(1e-5f, 0, 0)), n); // almost parallel
    }
}
