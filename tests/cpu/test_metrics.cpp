// Error metrics of an AO image against a reference: known inputs with hand-computed outputs, and the
// fast separable SSIM checked against a direct 2-D window sum.
#include "metrics/error_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace ssao;

namespace {

constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;

// Deterministic noise in [0,1) (LCG), so the tests need no <random> distribution guarantees.
std::vector<float> noise(int n, unsigned seed) {
    std::vector<float> v(size_t(n), 0.0f);
    for (float& x : v) {
        seed = seed * 1664525u + 1013904223u;
        x = float(seed >> 8) / float(1u << 24);
    }
    return v;
}

// SSIM of two constant images a and b: the contrast/structure term is C2/C2 = 1, leaving luminance.
const auto constantSsim = [](double a, double b) { return (2 * a * b + kC1) / (a * a + b * b + kC1); };

// Direct (non-separable) 2-D Gaussian window SSIM, same definition as ssim(): valid positions only
// in dimensions >= 11 px, clipped and renormalised window in smaller ones.
double bruteSsim(const std::vector<float>& a, const std::vector<float>& b, int w, int h) {
    const int x0 = w < 11 ? 0 : 5, x1 = w < 11 ? w - 1 : w - 6;
    const int y0 = h < 11 ? 0 : 5, y1 = h < 11 ? h - 1 : h - 6;
    double total = 0, count = 0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            double m[6] = {0, 0, 0, 0, 0, 0}; // weight sum, E[a], E[b], E[a^2], E[b^2], E[ab]
            for (int dy = -5; dy <= 5; ++dy)
                for (int dx = -5; dx <= 5; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
                    const double g = std::exp(-(dx * dx + dy * dy) / (2 * 1.5 * 1.5));
                    const double va = a[size_t(yy * w + xx)], vb = b[size_t(yy * w + xx)];
                    const double v[6] = {1, va, vb, va * va, vb * vb, va * vb};
                    for (int k = 0; k < 6; ++k)
                        m[k] += g * v[k];
                }
            const double ma = m[1] / m[0], mb = m[2] / m[0];
            const double va = m[3] / m[0] - ma * ma, vb = m[4] / m[0] - mb * mb, cab = m[5] / m[0] - ma * mb;
            total += (2 * ma * mb + kC1) * (2 * cab + kC2) / ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
            ++count;
        }
    return total / count;
}

// A w x h frame: geometry everywhere unless told, depth 1.
struct Frame {
    int w, h;
    std::vector<float> test, ref, geo, depth;
    Frame(int w_, int h_, float t, float r)
        : w(w_), h(h_), test(size_t(w * h), t), ref(size_t(w * h), r), geo(size_t(w * h), 1.0f),
          depth(size_t(w * h), 1.0f) {}
    MetricsInput input(bool withDepth = true) const {
        return {w, h, test.data(), ref.data(), geo.data(), withDepth ? depth.data() : nullptr, nullptr};
    }
};

// All geometry, depth 1 on x < w/2 and 2 beyond: the step lies between columns w/2-1 and w/2.
Frame depthStep(int w, int h) {
    Frame f(w, h, 0.5f, 0.5f);
    for (size_t i = 0; i < f.depth.size(); ++i)
        f.depth[i] = int(i % size_t(w)) < w / 2 ? 1.0f : 2.0f;
    return f;
}

} // namespace

TEST(ErrorMetrics, IdenticalImagesAreErrorFree) {
    Frame f(32, 24, 0, 0);
    f.ref = f.test = noise(32 * 24, 7);
    std::fill(f.geo.begin(), f.geo.begin() + 32 * 5, 0.0f); // top rows sky
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_EQ(e.pixels, 32 * 24);
    EXPECT_EQ(e.geometryPixels, 32 * 19);
    EXPECT_EQ(e.nonFinite, 0);
    for (double v : {e.rmse, e.mae, e.bias, e.p99Abs, e.maxAbs})
        EXPECT_EQ(v, 0.0);
    EXPECT_EQ(e.psnrGeometrySrgb, 100.0);
    EXPECT_EQ(e.psnrFullSrgb, 100.0);
    EXPECT_NEAR(e.ssim, 1.0, 1e-12);
    EXPECT_EQ(computeErrorMetrics(f.input(), MetricsOptions{3, 0.05f, 80.0}).psnrFullSrgb, 80.0);
}

TEST(ErrorMetrics, ConstantOffsetOnGeometryExcludesSky) {
    Frame f(8, 8, 0.6f, 0.5f);
    for (size_t i = 0; i < 64; ++i)
        if (i % 8 >= 4) f.geo[i] = 0.0f, f.test[i] = 0.0f, f.ref[i] = 1.0f; // sky (right half): ignored
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_EQ(e.geometryPixels, 32);
    for (double v : {e.rmse, e.mae, e.bias, e.p99Abs, e.maxAbs})
        EXPECT_NEAR(v, 0.1, 1e-6);
}

TEST(ErrorMetrics, BiasIsTestMinusReference) {
    Frame bright(4, 4, 0.9f, 0.7f), dark(4, 4, 0.3f, 0.7f);
    EXPECT_NEAR(computeErrorMetrics(bright.input()).bias, 0.2, 1e-6); // under-occlusion: positive
    EXPECT_NEAR(computeErrorMetrics(dark.input()).bias, -0.4, 1e-6);  // over-occlusion: negative
    EXPECT_NEAR(computeErrorMetrics(dark.input()).mae, 0.4, 1e-6);
}

TEST(ErrorMetrics, HandComputedRmseMaeP99) {
    // 10 geometry pixels, errors {+.1, -.2, +.3, -.4, 0 x6}, plus 2 sky pixels with error.
    Frame f(12, 1, 0.5f, 0.5f);
    f.test[0] = 0.6f, f.test[1] = 0.3f, f.test[2] = 0.8f, f.test[3] = 0.1f;
    f.geo[10] = f.geo[11] = f.test[10] = f.test[11] = 0.0f;
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_EQ(e.geometryPixels, 10);
    EXPECT_NEAR(e.rmse, std::sqrt(0.30 / 10), 1e-6); // .01 + .04 + .09 + .16
    EXPECT_NEAR(e.mae, 1.0 / 10, 1e-6);
    EXPECT_NEAR(e.bias, -0.2 / 10, 1e-6);
    // Sorted |err|: 0 x6, .1, .2, .3, .4; rank 0.99 * 9 = 8.91 -> .3 + .91 * (.4 - .3).
    EXPECT_NEAR(e.p99Abs, 0.391, 1e-6);
    EXPECT_NEAR(e.maxAbs, 0.4, 1e-6);
}

TEST(ErrorMetrics, SrgbEncodeKnownPoints) {
    EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_NEAR(linearToSrgb(1.0f), 1.0f, 1e-7);
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.04045f, 1e-5); // where the two pieces meet
    EXPECT_NEAR(linearToSrgb(0.001f), 0.01292f, 1e-7);     // linear segment
    EXPECT_NEAR(linearToSrgb(0.5f), 0.7353569830, 1e-6);
    EXPECT_NEAR(linearToSrgb(0.18f), 0.4613561295, 1e-6); // middle grey
    EXPECT_EQ(linearToSrgb(-0.5f), 0.0f);                 // clamped
    EXPECT_NEAR(linearToSrgb(3.0f), 1.0f, 1e-7);
    EXPECT_TRUE(std::isnan(linearToSrgb(std::numeric_limits<float>::quiet_NaN())));
}

TEST(ErrorMetrics, FullFramePsnrIncludesSky) {
    // 2x2: geometry {test .5 / ref 0, equal}, sky {test 0 / ref 1, equal}.
    Frame f(2, 2, 1.0f, 1.0f);
    f.test[0] = 0.5f, f.ref[0] = 0.0f;
    f.geo[2] = f.geo[3] = f.test[2] = 0.0f;
    const double s = 0.7353569830; // sRGB of 0.5
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_NEAR(e.psnrGeometrySrgb, 10 * std::log10(2 / (s * s)), 1e-5);
    EXPECT_NEAR(e.psnrFullSrgb, 10 * std::log10(4 / (s * s + 1)), 1e-5);
    // Error only in the sky: the geometry PSNR is capped, the full-frame one is not.
    f.test[0] = f.ref[0];
    const ErrorMetrics sky = computeErrorMetrics(f.input());
    EXPECT_EQ(sky.psnrGeometrySrgb, 100.0);
    EXPECT_NEAR(sky.psnrFullSrgb, 10 * std::log10(4.0), 1e-9);
}

TEST(ErrorMetrics, SsimOfConstantImagesDirect) {
    const std::vector<float> a(32 * 20, 0.3f), b(32 * 20, 0.6f);
    EXPECT_NEAR(ssim(a.data(), b.data(), 32, 20), constantSsim(0.3, 0.6), 1e-9);
    EXPECT_NEAR(ssim(a.data(), a.data(), 32, 20), 1.0, 1e-12);
    // Smaller than the window: clipped window, same answer for constants.
    EXPECT_NEAR(ssim(a.data(), b.data(), 5, 3), constantSsim(0.3, 0.6), 1e-9);
    EXPECT_NEAR(ssim(a.data(), b.data(), 40, 4), constantSsim(0.3, 0.6), 1e-9);
}

TEST(ErrorMetrics, SsimThroughComputeIsInSrgb) {
    Frame f(16, 16, 0.5f, 0.2f);
    const double sa = 0.7353569830, sb = 0.4845292045; // sRGB of 0.5 and 0.2
    EXPECT_NEAR(computeErrorMetrics(f.input()).ssim, constantSsim(sa, sb), 1e-6);
}

TEST(ErrorMetrics, SsimSymmetricAndBelowOneForNoise) {
    const int w = 48, h = 36;
    const std::vector<float> a = noise(w * h, 1), n = noise(w * h, 2);
    std::vector<float> b = a, c = a; // mild and strong noise on top of a
    for (size_t i = 0; i < b.size(); ++i)
        b[i] += 0.2f * (n[i] - 0.5f), c[i] += 0.6f * (n[i] - 0.5f);
    const double ab = ssim(a.data(), b.data(), w, h), ba = ssim(b.data(), a.data(), w, h);
    EXPECT_NEAR(ab, ba, 1e-12);
    EXPECT_LT(ab, 0.99);
    EXPECT_GT(ab, 0.5); // mild noise on a noise image: still clearly similar
    EXPECT_NEAR(ssim(a.data(), a.data(), w, h), 1.0, 1e-12);
    EXPECT_LT(ssim(a.data(), c.data(), w, h), ab); // stronger noise is less similar
}

TEST(ErrorMetrics, SsimMatchesDirectWindowSum) {
    const int sizes[3][2] = {{23, 17}, {7, 30}, {9, 6}}; // full windows, one side clipped, both clipped
    for (const auto& s : sizes) {
        const std::vector<float> a = noise(s[0] * s[1], 3), b = noise(s[0] * s[1], 4);
        std::vector<float> c(a.size());
        for (size_t i = 0; i < c.size(); ++i)
            c[i] = 0.7f * a[i] + 0.3f * b[i]; // correlated with a, so the structure term matters
        EXPECT_NEAR(ssim(a.data(), c.data(), s[0], s[1]), bruteSsim(a, c, s[0], s[1]), 1e-10)
            << s[0] << "x" << s[1];
    }
}

TEST(ErrorMetrics, EdgeMaskFlagsDepthStep) {
    const int w = 20, h = 8;
    const Frame f = depthStep(w, h); // step between columns 9 and 10
    const std::vector<unsigned char> m = edgeMask(f.geo.data(), f.depth.data(), w, h, 3, 0.05f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int dist = x < 10 ? 9 - x : x - 10; // px from the pixel touching the step
            EXPECT_EQ(m[size_t(y * w + x)], dist <= 3 ? 1 : 0) << x << "," << y;
        }
}

TEST(ErrorMetrics, EdgeMaskFlagsGeometrySkyBorder) {
    const int w = 6, h = 12; // rows 0..3 sky, rows 4.. geometry at constant depth
    Frame f(w, h, 0.5f, 0.5f);
    std::fill(f.geo.begin(), f.geo.begin() + 4 * w, 0.0f);
    for (const float* d : {f.depth.data(), static_cast<float*>(nullptr)}) { // with depth, and without
        const std::vector<unsigned char> m = edgeMask(f.geo.data(), d, w, h, 3, 0.05f);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                EXPECT_EQ(m[size_t(y * w + x)], y >= 4 && y <= 7 ? 1 : 0) << x << "," << y; // sky never
    }
}

TEST(ErrorMetrics, EdgeMaskIgnoresSmoothRamp) {
    const int w = 64, h = 64; // grazing plane: depth grows 0.1 % per pixel in x, 0.05 % in y
    std::vector<float> depth(size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            depth[size_t(y * w + x)] = 10.0f * std::pow(1.001f, float(x)) * std::pow(1.0005f, float(y));
    const std::vector<unsigned char> m = edgeMask(nullptr, depth.data(), w, h, 3, 0.05f); // all geometry
    EXPECT_EQ(std::count(m.begin(), m.end(), 1), 0);
}

TEST(ErrorMetrics, EdgeInteriorRmseSplit) {
    Frame f = depthStep(20, 4); // edge columns 6..13 get error 0.2
    for (int y = 0; y < 4; ++y)
        for (int x = 6; x <= 13; ++x)
            f.test[size_t(y * 20 + x)] = 0.7f;
    f.test[0] = 0.9f; // one interior pixel off by 0.4
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_EQ(e.edgePixels, 32);
    EXPECT_EQ(e.interiorPixels, 48);
    EXPECT_NEAR(e.rmseEdge, 0.2, 1e-6);
    EXPECT_NEAR(e.rmseInterior, std::sqrt(0.16 / 48), 1e-6);
    EXPECT_NEAR(e.rmse, std::sqrt((32 * 0.04 + 0.16) / 80), 1e-6);
    // No depth: no split.
    const ErrorMetrics nd = computeErrorMetrics(f.input(false));
    EXPECT_EQ(nd.edgePixels + nd.interiorPixels, 0);
    EXPECT_TRUE(std::isnan(nd.rmseEdge) && std::isnan(nd.rmseInterior));
    // Flat depth, all geometry: the edge set is empty, so its RMSE is NaN.
    Frame flat(20, 4, 0.6f, 0.5f);
    const ErrorMetrics fl = computeErrorMetrics(flat.input());
    EXPECT_EQ(fl.edgePixels, 0);
    EXPECT_TRUE(std::isnan(fl.rmseEdge));
    EXPECT_NEAR(fl.rmseInterior, 0.1, 1e-6);
}

TEST(ErrorMetrics, NonFiniteTestPixelsCountAsWhite) {
    Frame f(16, 16, 0.5f, 0.5f);
    const float inf = std::numeric_limits<float>::infinity();
    f.test[3] = std::numeric_limits<float>::quiet_NaN(), f.test[40] = inf, f.test[77] = -inf;
    f.geo[77] = 0.0f; // on sky: counted, but not in the geometry metrics
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_EQ(e.nonFinite, 3);
    // Two geometry pixels read as 1.0 against 0.5 out of 255.
    EXPECT_NEAR(e.rmse, std::sqrt(2 * 0.25 / 255), 1e-6);
    EXPECT_NEAR(e.bias, 2 * 0.5 / 255, 1e-6);
    EXPECT_NEAR(e.maxAbs, 0.5, 1e-6);
    for (double v :
         {e.rmse, e.mae, e.bias, e.p99Abs, e.psnrGeometrySrgb, e.psnrFullSrgb, e.ssim, e.rmseInterior})
        EXPECT_TRUE(std::isfinite(v));
    EXPECT_LT(e.ssim, 1.0);
}

TEST(ErrorMetrics, ReferenceNoiseIsRmsOverGeometry) {
    Frame f(3, 1, 0.5f, 0.5f);
    const std::vector<float> se = {0.03f, 0.04f, 1.0f};
    f.geo[2] = 0.0f; // the sky's large value is ignored
    MetricsInput in = f.input();
    EXPECT_EQ(computeErrorMetrics(in).referenceNoise, 0.0); // null: no noise
    in.referenceStdErr = se.data();
    EXPECT_NEAR(computeErrorMetrics(in).referenceNoise, std::sqrt((0.0009 + 0.0016) / 2), 1e-7);
}

TEST(ErrorMetrics, NoGeometryGivesZerosAndCap) {
    Frame f(8, 8, 0.2f, 0.9f);
    std::fill(f.geo.begin(), f.geo.end(), 0.0f);
    const ErrorMetrics e = computeErrorMetrics(f.input());
    EXPECT_EQ(e.geometryPixels, 0);
    for (double v : {e.rmse, e.mae, e.bias, e.p99Abs, e.maxAbs, e.referenceNoise})
        EXPECT_EQ(v, 0.0);
    EXPECT_EQ(e.psnrGeometrySrgb, 100.0);
    EXPECT_LT(e.psnrFullSrgb, 100.0); // the sky still differs
    EXPECT_TRUE(std::isnan(e.rmseEdge) && std::isnan(e.rmseInterior));
}

TEST(ErrorMetrics, MissingImagesThrow) {
    MetricsInput in;
    in.width = in.height = 4;
    EXPECT_THROW(computeErrorMetrics(in), std::invalid_argument);
    in.width = in.height = 0;
    EXPECT_EQ(computeErrorMetrics(in).pixels, 0);
}
