#include "metrics/motion_metrics.h"

#include "metrics/error_metrics.h"
#include "metrics/reprojection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ssao {

std::string ghostingText(const MotionMetrics& m) {
    if (!std::isfinite(m.ghosting)) return "n/a (" + std::to_string(m.disoccludedPixels) + " pixels)";
    char b[32];
    std::snprintf(b, sizeof b, "%+.4f", m.ghosting);
    return b;
}

double motionScore(double rmseMean, double instability) {
    const double i = std::isfinite(instability) ? instability : 0.0;
    return std::sqrt(rmseMean * rmseMean + i * i);
}

double motionScore(const MotionMetrics& m) {
    return motionScore(m.rmseMean, m.instability);
}

double motionObjective(const MotionMetrics& m) {
    const double s = motionScore(m);
    return s * s;
}

namespace {

float value(float v) {
    return std::isfinite(v) ? v : 1.0f;
}

bool counted(const MotionFrameInput& f, size_t i) {
    return (!f.geometry || f.geometry[i] > 0.0f) && !(f.exclude && f.exclude[i] > 0.0f);
}

// Running sums of the three measures.
struct Sums {
    double d2 = 0, floor2 = 0, fresh = 0, stable = 0, stableEdge = 0;
    long pairs = 0, freshN = 0, stableN = 0, stableEdgeN = 0;
};

// Each pixel's frames since it became visible (kOld: since before the path), and whether it came
// in at the frame's edge rather than from behind a surface.
constexpr int kOld = 1 << 20;

void frameSums(const MotionFrameInput& cur, const MotionFrameInput& prev, int w, int h, const MotionOptions& opt,
               std::vector<int>& age, std::vector<unsigned char>& entered, Sums& s) {
    const size_t n = size_t(w) * size_t(h);
    const std::vector<unsigned char> edges =
        cur.depth ? edgeMask(cur.geometry, cur.depth, w, h, MetricsOptions{}.edgeRadiusPx, MetricsOptions{}.edgeRelDepth)
                  : std::vector<unsigned char>(n, 0);
    std::vector<int> nextAge(n, kOld);
    std::vector<unsigned char> nextEntered(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (cur.geometry && !(cur.geometry[i] > 0.0f)) continue;
        const int j = cur.toPrevious ? cur.toPrevious[i] : kDisoccluded;
        if (j >= 0) {
            nextAge[i] = std::min(age[size_t(j)], kOld - 1) + 1;
            nextEntered[i] = entered[size_t(j)];
        } else {
            nextAge[i] = 1;
            nextEntered[i] = j == kOffScreen;
        }
        if (!counted(cur, i)) continue;
        const double err = std::abs(double(value(cur.test[i])) - cur.reference[i]);
        if (nextAge[i] > opt.ghostFrames) {
            s.stable += err, ++s.stableN;
            if (edges[i]) s.stableEdge += err, ++s.stableEdgeN;
        } else if (!nextEntered[i]) {
            s.fresh += err, ++s.freshN;
        }
        if (j < 0 || !counted(prev, size_t(j))) continue;
        const double dt = double(value(cur.test[i])) - value(prev.test[size_t(j)]);
        const double dr = double(cur.reference[i]) - prev.reference[size_t(j)];
        s.d2 += (dt - dr) * (dt - dr);
        const double a = cur.referenceStdErr ? cur.referenceStdErr[i] : 0.0;
        const double b = prev.referenceStdErr ? prev.referenceStdErr[size_t(j)] : 0.0;
        s.floor2 += a * a + b * b;
        ++s.pairs;
    }
    age.swap(nextAge);
    entered.swap(nextEntered);
}

} // namespace

MotionMetrics computeMotionMetrics(int w, int h, const std::vector<MotionFrameInput>& frames, const MotionOptions& opt) {
    if (w < 0 || h < 0) throw std::invalid_argument("computeMotionMetrics: negative size");
    for (const auto& f : frames)
        if (w * h > 0 && (!f.test || !f.reference))
            throw std::invalid_argument("computeMotionMetrics: a frame lacks its test or reference image");
    MotionMetrics m;
    m.frames = int(frames.size());
    for (const auto& f : frames) {
        MetricsInput in;
        in.width = w, in.height = h, in.test = f.test, in.reference = f.reference, in.geometry = f.geometry;
        in.depth = f.depth, in.referenceStdErr = f.referenceStdErr, in.exclude = f.exclude;
        const double rmse = computeErrorMetrics(in).rmse;
        m.frameRmse.push_back(rmse);
        m.rmseMean += rmse / double(frames.size());
        m.mseMean += rmse * rmse / double(frames.size());
        m.rmseMax = std::max(m.rmseMax, rmse);
    }
    const size_t n = size_t(w) * size_t(h);
    std::vector<int> age(n, kOld);
    std::vector<unsigned char> entered(n, 0);
    Sums s;
    for (size_t k = 1; k < frames.size(); ++k)
        frameSums(frames[k], frames[k - 1], w, h, opt, age, entered, s);
    m.pairs = s.pairs;
    if (s.pairs) {
        m.instability = std::sqrt(s.d2 / double(s.pairs));
        m.instabilityFloor = std::sqrt(s.floor2 / double(s.pairs));
    }
    m.disoccludedPixels = s.freshN, m.stablePixels = s.stableN;
    if (s.freshN) m.disoccludedMae = s.fresh / double(s.freshN);
    if (s.stableN) m.stableMae = s.stable / double(s.stableN);
    if (s.stableEdgeN) m.stableEdgeMae = s.stableEdge / double(s.stableEdgeN);
    if (s.freshN >= std::max(1L, opt.minGhostPixels) && s.stableN) m.ghosting = m.disoccludedMae - m.stableMae;
    return m;
}

} // namespace ssao
