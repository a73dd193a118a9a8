#include "metrics/bench_summary.h"

#include "metrics/motion_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ssao {

int passCategory(const std::string& n) {
    if (n == "guard_band" || n == "back_faces" || n == "second_layer") return 1;
    if (n.rfind("gbuffer", 0) == 0) return 0;
    if (n.rfind("denoise", 0) == 0 || n.rfind("temporal", 0) == 0 || n.rfind("upsample", 0) == 0) return 3;
    if (n.rfind("composite", 0) == 0) return 4;
    if (n.rfind("reference", 0) == 0) return -1; // the explorer's upload of the reference, not the frame
    return 2; // the technique's passes and the position pyramid
}

double median(std::vector<double> v) {
    if (v.empty() || std::any_of(v.begin(), v.end(), [](double x) { return std::isnan(x); }))
        return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<bool> paretoFront(const std::vector<double>& time, const std::vector<double>& error) {
    const size_t n = time.size();
    std::vector<bool> front(n, true);
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(time[i]) || !std::isfinite(error[i])) {
            front[i] = false;
            continue;
        }
        for (size_t j = 0; j < n && front[i]; ++j) {
            if (j == i || !std::isfinite(time[j]) || !std::isfinite(error[j])) continue;
            const bool noWorse = time[j] <= time[i] && error[j] <= error[i];
            const bool better = time[j] < time[i] || error[j] < error[i];
            if (noWorse && better) front[i] = false;
        }
    }
    return front;
}

namespace {
// PSNR (peak 1) ↔ MSE, so views are averaged in MSE as XeGTAO's auto-tune does.
double mseOf(double psnr) {
    return std::pow(10.0, -psnr / 10.0);
}
double psnrOf(double mse) {
    return mse > 0 ? 10.0 * std::log10(1.0 / mse) : 100.0;
}
} // namespace

namespace {
// Each row's time against the baseline of its own run on its view.
void rowRatios(std::vector<ViewResult>& views, size_t baseline) {
    for (ViewResult& v : views) {
        double base = v.baselineMs;
        if (!std::isfinite(base))
            for (const ViewResult& b : views)
                if (b.config == baseline && b.scene == v.scene && b.viewpoint == v.viewpoint && b.shard == v.shard) {
                    base = b.gpuMs;
                    break;
                }
        v.timeRatio = base > 0 ? v.gpuMs / base : std::numeric_limits<double>::quiet_NaN();
    }
}
} // namespace

namespace {
// RMS over the views that have a split (NaN when none).
SplitSummary splitOf(const std::vector<const ErrorMetrics*>& m) {
    SplitSummary s;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double mse = 0, edge = 0, interior = 0;
    int edges = 0, interiors = 0;
    for (const ErrorMetrics* e : m) {
        mse += e->rmse * e->rmse;
        s.bias += e->bias;
        if (std::isfinite(e->rmseEdge)) edge += e->rmseEdge * e->rmseEdge, ++edges;
        if (std::isfinite(e->rmseInterior)) interior += e->rmseInterior * e->rmseInterior, ++interiors;
    }
    if (m.empty()) return {nan, nan, nan, nan};
    s.rmse = std::sqrt(mse / double(m.size()));
    s.bias /= double(m.size());
    s.rmseEdge = edges ? std::sqrt(edge / edges) : nan;
    s.rmseInterior = interiors ? std::sqrt(interior / interiors) : nan;
    return s;
}
// Over the rows of one configuration that were measured in motion.
MotionSummary motionOf(const std::vector<const MotionSummary*>& m) {
    MotionSummary s;
    double mse = 0, inst = 0, ghost = 0;
    int insts = 0, ghosts = 0;
    for (const MotionSummary* v : m) {
        mse += v->rmseMean * v->rmseMean;
        s.rmseMax = std::isnan(s.rmseMax) ? v->rmseMax : std::max(s.rmseMax, v->rmseMax);
        if (std::isfinite(v->instability)) inst += v->instability * v->instability, ++insts;
        if (std::isfinite(v->ghosting)) ghost += v->ghosting, ++ghosts;
    }
    if (m.empty()) return s;
    s.rmseMean = std::sqrt(mse / double(m.size()));
    if (insts) s.instability = std::sqrt(inst / insts);
    if (ghosts) s.ghosting = ghost / ghosts;
    return s;
}
} // namespace

const char* objectiveKey(Objective o) {
    return o == Objective::Motion ? "motion" : "still";
}

Objective parseObjective(const std::string& key) {
    if (key == "still") return Objective::Still;
    if (key == "motion") return Objective::Motion;
    throw std::invalid_argument("objective '" + key + "' is neither 'still' nor 'motion'");
}

const char* objectiveErrorName(Objective o) {
    return o == Objective::Motion ? "motion score" : "RMSE";
}

const char* objectiveTitle(Objective o) {
    return o == Objective::Motion ? "the motion score" : "the still frame's RMSE";
}

const char* objectiveWhere(Objective o) {
    return o == Objective::Motion ? "in motion" : "on a still camera";
}

double objectiveError(const ConfigSummary& s, Objective o) {
    return o == Objective::Motion ? s.motionScore : s.rmse;
}

double objectiveRatio(const ConfigSummary& s, Objective o) {
    return o == Objective::Motion ? s.motionRatio : s.rmseRatio;
}

std::vector<ConfigSummary> summarize(std::vector<ViewResult>& views, size_t configCount, size_t baseline,
                                     Objective objective) {
    rowRatios(views, baseline);
    std::vector<ConfigSummary> out(configCount);
    for (size_t c = 0; c < configCount; ++c) {
        ConfigSummary& s = out[c];
        s.config = c;
        std::vector<const ErrorMetrics*> technique, screen;
        std::vector<const MotionSummary*> motion;
        double mse = 0, mseGeo = 0, mseFull = 0, edge = 0, interior = 0, mseFirst = 0, logRatio = 0;
        int edgeViews = 0, interiorViews = 0, ratioViews = 0;
        s.gpuMsMin = std::numeric_limits<double>::infinity();
        s.gpuMsMax = -s.gpuMsMin;
        double passSum[PassTimes::kParts] = {0, 0, 0, 0, 0};
        for (const ViewResult& v : views) {
            if (v.config != c) continue;
            ++s.views;
            s.gpuMs += v.gpuMs;
            for (int k = 0; k < PassTimes::kParts; ++k)
                passSum[k] += v.passMs.ms[k];
            s.gpuMsMin = std::min(s.gpuMsMin, v.gpuMsMin);
            s.gpuMsMax = std::max(s.gpuMsMax, v.gpuMsMax);
            s.unsureTimeViews += v.gpuMsMax > kUnsureTimeSpread * v.gpuMs;
            mse += v.error.rmse * v.error.rmse;
            mseFirst += v.rmseFirstFrame * v.rmseFirstFrame;
            s.mae += v.error.mae;
            s.bias += v.error.bias;
            mseGeo += mseOf(v.error.psnrGeometrySrgb);
            mseFull += mseOf(v.error.psnrFullSrgb);
            if (std::isfinite(v.error.rmseEdge)) edge += v.error.rmseEdge * v.error.rmseEdge, ++edgeViews;
            if (std::isfinite(v.error.rmseInterior))
                interior += v.error.rmseInterior * v.error.rmseInterior, ++interiorViews;
            s.ssim += v.error.ssim;
            s.nonFinite += v.error.nonFinite;
            if (std::isfinite(v.timeRatio) && v.timeRatio > 0) logRatio += std::log(v.timeRatio), ++ratioViews;
            if (v.hasSplit) technique.push_back(&v.vsOracle), screen.push_back(&v.screen);
            if (v.hasMotion) motion.push_back(&v.motion);
        }
        s.technique = splitOf(technique);
        s.screen = splitOf(screen);
        s.motion = motionOf(motion);
        if (s.views == 0) {
            const double nan = std::numeric_limits<double>::quiet_NaN();
            s.gpuMs = s.gpuMsMin = s.gpuMsMax = s.rmse = s.mae = s.bias = nan;
            s.psnrGeometrySrgb = s.psnrFullSrgb = s.rmseEdge = s.rmseInterior = s.ssim = s.rmseFirstFrame =
                nan;
            continue;
        }
        const double n = s.views;
        s.gpuMs /= n;
        for (int k = 0; k < PassTimes::kParts; ++k)
            s.passMs.ms[k] = passSum[k] / n; // NaN if a view lacks one
        s.rmse = std::sqrt(mse / n);
        s.rmseFirstFrame = std::sqrt(mseFirst / n);
        s.mae /= n;
        s.bias /= n;
        s.psnrGeometrySrgb = psnrOf(mseGeo / n);
        s.psnrFullSrgb = psnrOf(mseFull / n);
        s.rmseEdge = edgeViews ? std::sqrt(edge / edgeViews) : std::numeric_limits<double>::quiet_NaN();
        s.rmseInterior =
            interiorViews ? std::sqrt(interior / interiorViews) : std::numeric_limits<double>::quiet_NaN();
        s.ssim /= n;
        s.timeRatio = ratioViews ? std::exp(logRatio / ratioViews) : std::numeric_limits<double>::quiet_NaN();
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (ConfigSummary& s : out)
        if (std::isfinite(s.motion.rmseMean)) s.motionScore = motionScore(s.motion.rmseMean, s.motion.instability);
    std::vector<double> t, e;
    for (const auto& s : out)
        t.push_back(s.timeRatio), e.push_back(objectiveError(s, objective));
    const std::vector<bool> front = paretoFront(t, e);
    for (size_t c = 0; c < configCount; ++c) {
        out[c].pareto = front[c];
        out[c].rmseRatio = baseline < configCount ? out[c].rmse / out[baseline].rmse : nan;
        out[c].motionRatio = baseline < configCount ? out[c].motionScore / out[baseline].motionScore : nan;
    }
    return out;
}

} // namespace ssao
