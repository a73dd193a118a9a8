// Image error metrics of an AO image against a reference: plain loops in double over float arrays, and
// a separable Gaussian SSIM so that a 1280x720 frame costs ~11 taps per pixel per pass.
#include "metrics/error_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ssao {

namespace {

constexpr int kSsimRadius = 5;      // 11-tap window: skimage's int(truncate 3.5 * sigma 1.5 + 0.5)
constexpr double kSsimSigma = 1.5;  // Wang et al. 2004, Sec. III-C
constexpr double kC1 = 0.01 * 0.01; // (K1 L)^2, K1 = 0.01, L = 1
constexpr double kC2 = 0.03 * 0.03; // (K2 L)^2, K2 = 0.03, L = 1

// One output position of a 1-D window pass: taps [first, first + count) of the input, with weights
// that sum to 1 (renormalised where the window is clipped by a small image).
struct Tap {
    int first = 0, count = 0;
    std::array<double, 2 * kSsimRadius + 1> w{};
};

// The output positions along one dimension of n pixels: those whose full window fits (skimage crops
// the rest), or all of them, with the clipped window, when n is smaller than the window.
std::vector<Tap> windowTaps(int n) {
    std::array<double, 2 * kSsimRadius + 1> g{};
    for (int k = -kSsimRadius; k <= kSsimRadius; ++k)
        g[k + kSsimRadius] = std::exp(-0.5 * k * k / (kSsimSigma * kSsimSigma));
    const bool clipped = n < 2 * kSsimRadius + 1;
    const int p0 = clipped ? 0 : kSsimRadius, p1 = clipped ? n - 1 : n - 1 - kSsimRadius;
    std::vector<Tap> taps;
    for (int p = p0; p <= p1; ++p) {
        Tap t;
        const int lo = std::max(-kSsimRadius, -p), hi = std::min(kSsimRadius, n - 1 - p);
        t.first = p + lo;
        t.count = hi - lo + 1;
        double sum = 0.0;
        for (int k = lo; k <= hi; ++k)
            sum += g[k + kSsimRadius];
        for (int k = lo; k <= hi; ++k)
            t.w[k - lo] = g[k + kSsimRadius] / sum;
        taps.push_back(t);
    }
    return taps;
}

// PSNR (dB) for peak 1: 10 log10(1 / MSE), capped so that identical images give a finite number.
double psnr(double mse, double cap) {
    if (!(mse > 0.0)) return cap;
    return std::min(cap, 10.0 * std::log10(1.0 / mse));
}

// Percentile p in [0,1] with linear interpolation between order statistics (numpy's default), so the
// number can be checked against np.percentile. Reorders `v`.
double percentile(std::vector<float>& v, double p) {
    if (v.empty()) return 0.0;
    const double pos = p * double(v.size() - 1);
    const size_t lo = size_t(std::floor(pos));
    std::nth_element(v.begin(), v.begin() + long(lo), v.end());
    const double vlo = v[lo];
    if (lo + 1 >= v.size()) return vlo;
    // After nth_element everything past lo is >= v[lo]; the next order statistic is their minimum.
    const double vhi = *std::min_element(v.begin() + long(lo) + 1, v.end());
    return vlo + (pos - double(lo)) * (vhi - vlo);
}

// out[i] = 1 where some in[j] on the same row (dx = 1) or column (dx = width) lies within r steps.
// Prefix counts make it O(n) whatever r is.
void dilateLine(const std::vector<unsigned char>& in, std::vector<unsigned char>& out, int width, int height,
                int r, bool rows) {
    const int lines = rows ? height : width, len = rows ? width : height;
    const int stride = rows ? 1 : width;
    std::vector<int> prefix(size_t(len) + 1);
    for (int l = 0; l < lines; ++l) {
        const int base = rows ? l * width : l;
        for (int i = 0; i < len; ++i)
            prefix[size_t(i) + 1] = prefix[size_t(i)] + (in[size_t(base + i * stride)] ? 1 : 0);
        for (int i = 0; i < len; ++i) {
            const int a = std::max(0, i - r), b = std::min(len - 1, i + r);
            out[size_t(base + i * stride)] = prefix[size_t(b) + 1] - prefix[size_t(a)] > 0 ? 1 : 0;
        }
    }
}

} // namespace

float linearToSrgb(float v) {
    if (std::isnan(v)) return v;
    const double x = std::clamp(double(v), 0.0, 1.0);
    // IEC 61966-2-1: linear segment near black, 2.4 power law with offset above.
    return float(x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055);
}

double ssim(const float* a, const float* b, int width, int height) {
    if (width <= 0 || height <= 0) return 1.0;
    const std::vector<Tap> tx = windowTaps(width), ty = windowTaps(height);
    const size_t nx = tx.size();
    // Horizontal pass over every row of the five local moments: a, b, a^2, b^2, ab.
    std::vector<double> h(size_t(height) * nx * 5);
    for (int y = 0; y < height; ++y) {
        const float* ra = a + size_t(y) * size_t(width);
        const float* rb = b + size_t(y) * size_t(width);
        for (size_t i = 0; i < nx; ++i) {
            const Tap& t = tx[i];
            double s[5] = {0, 0, 0, 0, 0};
            for (int k = 0; k < t.count; ++k) {
                const double va = ra[t.first + k], vb = rb[t.first + k], w = t.w[size_t(k)];
                s[0] += w * va;
                s[1] += w * vb;
                s[2] += w * va * va;
                s[3] += w * vb * vb;
                s[4] += w * va * vb;
            }
            std::copy(s, s + 5, &h[(size_t(y) * nx + i) * 5]);
        }
    }
    // Vertical pass row by row, then the SSIM map (Wang et al. 2004, Eq. 13) summed on the fly.
    std::vector<double> m(nx * 5);
    double total = 0.0;
    for (const Tap& t : ty) {
        std::fill(m.begin(), m.end(), 0.0);
        for (int k = 0; k < t.count; ++k) {
            const double w = t.w[size_t(k)];
            const double* row = &h[size_t(t.first + k) * nx * 5];
            for (size_t j = 0; j < nx * 5; ++j)
                m[j] += w * row[j];
        }
        for (size_t i = 0; i < nx; ++i) {
            const double* q = &m[i * 5];
            const double ua = q[0], ub = q[1];
            // Population moments: E[x^2] - E[x]^2 (skimage's use_sample_covariance=False).
            const double va = q[2] - ua * ua, vb = q[3] - ub * ub, cab = q[4] - ua * ub;
            total +=
                ((2.0 * ua * ub + kC1) * (2.0 * cab + kC2)) / ((ua * ua + ub * ub + kC1) * (va + vb + kC2));
        }
    }
    return total / double(nx * ty.size());
}

std::vector<unsigned char> edgeMask(const float* geometry, const float* depth, int width, int height,
                                    int radiusPx, float relDepth) {
    if (width <= 0 || height <= 0) return {};
    const size_t n = size_t(width) * size_t(height);
    auto geo = [&](size_t i) { return geometry == nullptr || geometry[i] > 0.0f; };
    // Relative threshold: a step of 5% of the nearer depth, so a grazing plane (slow relative change per
    // pixel) stays smooth at any distance while an object in front of a wall does not.
    auto discontinuous = [&](size_t i, size_t j) {
        const bool gi = geo(i), gj = geo(j);
        if (gi != gj) return true;
        if (!gi || depth == nullptr) return false;
        const double zi = depth[i], zj = depth[j];
        return std::abs(zi - zj) > double(relDepth) * std::min(zi, zj);
    };
    std::vector<unsigned char> seed(n, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            if (x + 1 < width && discontinuous(i, i + 1)) seed[i] = seed[i + 1] = 1;
            if (y + 1 < height && discontinuous(i, i + size_t(width))) seed[i] = seed[i + size_t(width)] = 1;
        }
    // A Chebyshev ball is a square, so dilating rows then columns gives it exactly.
    const int r = std::max(0, radiusPx);
    std::vector<unsigned char> rows(n), mask(n);
    dilateLine(seed, rows, width, height, r, true);
    dilateLine(rows, mask, width, height, r, false);
    for (size_t i = 0; i < n; ++i)
        if (!geo(i)) mask[i] = 0;
    return mask;
}

ErrorMetrics computeErrorMetrics(const MetricsInput& in, const MetricsOptions& opt) {
    if (in.width < 0 || in.height < 0)
        throw std::invalid_argument("computeErrorMetrics: negative image size");
    const size_t n = size_t(in.width) * size_t(in.height);
    if (n > 0 && (in.test == nullptr || in.reference == nullptr))
        throw std::invalid_argument("computeErrorMetrics: test and reference images are required");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    ErrorMetrics e;
    e.pixels = long(n);
    auto excluded = [&](size_t i) { return in.exclude != nullptr && in.exclude[i] > 0.0f; };
    auto geo = [&](size_t i) { return (in.geometry == nullptr || in.geometry[i] > 0.0f) && !excluded(i); };

    // Non-finite test values become 1.0 (unoccluded, what an R8 target shows) for every metric.
    std::vector<float> test(n), srgbTest(n), srgbRef(n);
    for (size_t i = 0; i < n; ++i) {
        const bool finite = std::isfinite(in.test[i]);
        e.nonFinite += finite ? 0 : 1;
        test[i] = finite ? in.test[i] : 1.0f;
        if (excluded(i)) {
            ++e.excludedPixels;
            test[i] = in.reference[i];
        }
        srgbTest[i] = linearToSrgb(test[i]);
        srgbRef[i] = linearToSrgb(in.reference[i]);
    }

    std::vector<float> absErr;
    double sum = 0, sumAbs = 0, sumSq = 0, sumSrgbSqGeo = 0, sumSrgbSqAll = 0, sumStdErrSq = 0, maxAbs = 0;
    for (size_t i = 0; i < n; ++i) {
        const double ds = double(srgbTest[i]) - double(srgbRef[i]);
        sumSrgbSqAll += ds * ds;
        if (!geo(i)) continue;
        const double d = double(test[i]) - double(in.reference[i]);
        ++e.geometryPixels;
        sum += d;
        sumAbs += std::abs(d);
        sumSq += d * d;
        maxAbs = std::max(maxAbs, std::abs(d));
        absErr.push_back(float(std::abs(d)));
        sumSrgbSqGeo += ds * ds;
        if (in.referenceStdErr) sumStdErrSq += double(in.referenceStdErr[i]) * double(in.referenceStdErr[i]);
    }
    const double g = double(e.geometryPixels);
    if (e.geometryPixels > 0) {
        e.rmse = std::sqrt(sumSq / g);
        e.mae = sumAbs / g;
        e.bias = sum / g;
        e.maxAbs = maxAbs;
        e.p99Abs = percentile(absErr, 0.99);
        e.referenceNoise = std::sqrt(sumStdErrSq / g);
    }
    e.psnrGeometrySrgb = e.geometryPixels > 0 ? psnr(sumSrgbSqGeo / g, opt.psnrCap) : opt.psnrCap;
    e.psnrFullSrgb = n > 0 ? psnr(sumSrgbSqAll / double(n), opt.psnrCap) : opt.psnrCap;

    // Edge / interior split of the linear RMSE over geometry pixels.
    e.rmseEdge = e.rmseInterior = nan;
    if (in.depth != nullptr && n > 0) {
        const std::vector<unsigned char> edge =
            edgeMask(in.geometry, in.depth, in.width, in.height, opt.edgeRadiusPx, opt.edgeRelDepth);
        double sqEdge = 0, sqInterior = 0;
        for (size_t i = 0; i < n; ++i) {
            if (!geo(i)) continue;
            const double d = double(test[i]) - double(in.reference[i]);
            if (edge[i]) {
                ++e.edgePixels;
                sqEdge += d * d;
            } else {
                ++e.interiorPixels;
                sqInterior += d * d;
            }
        }
        if (e.edgePixels > 0) e.rmseEdge = std::sqrt(sqEdge / double(e.edgePixels));
        if (e.interiorPixels > 0) e.rmseInterior = std::sqrt(sqInterior / double(e.interiorPixels));
    }

    e.ssim = n > 0 ? ssim(srgbTest.data(), srgbRef.data(), in.width, in.height) : 1.0;
    return e;
}

} // namespace ssao
