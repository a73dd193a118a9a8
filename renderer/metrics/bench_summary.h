// Benchmark bookkeeping, pure: per-view measurements → one summary per configuration (time
// averaged over views, errors as the RMS over views, PSNR of the mean MSE as XeGTAO reports it),
// ratios to the baseline measured in the same run, and the time/error Pareto front.
// Times are only comparable on one machine: every row keeps its ratio to the baseline measured on
// the same view by the same run (a shard of a split benchmark, results/shard.h), and configurations
// are ranked by those ratios, so rows measured on different machines can be merged.
#pragma once
#include "metrics/error_metrics.h"
#include "metrics/error_places.h"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ssao {

// Where a frame's GPU time goes, ms (NaN: not run): the G-buffer, its extra layers (guard band,
// back faces: a remedy's own cost), the AO (the technique's passes and the position pyramid), the
// denoise stage (denoise, upsample, temporal) and the composite. ViewResult::gpuMs, what every row
// compares, is layers + ao + denoise: every pass but the G-buffer and the composite.
struct PassTimes {
    static constexpr int kParts = 5;
    static constexpr const char* kNames[kParts] = {"gbuffer", "layers", "ao", "denoise", "composite"};
    double ms[kParts] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::quiet_NaN()};
};
// The part of a frame-graph pass by its name, an index into PassTimes (-1: not part of the frame).
int passCategory(const std::string& passName);

// Error in motion (metrics/motion_metrics.h; bench --motion), NaN where not measured. Per view: the
// mean and max per-frame RMSE over the path, the instability, the ghosting excess. Per
// configuration: the RMS over views of the mean RMSE and of the instability, the max of the
// maxima, the mean of the ghosting over the views that had disoccluded pixels.
struct MotionSummary {
    double rmseMean = std::numeric_limits<double>::quiet_NaN(), rmseMax = std::numeric_limits<double>::quiet_NaN();
    double instability = std::numeric_limits<double>::quiet_NaN(), ghosting = std::numeric_limits<double>::quiet_NaN();
};

struct ViewResult {
    std::string scene, viewpoint;
    PassTimes passMs; // medians over the timed frames
    size_t config = 0;
    double gpuMs = 0, gpuMsMin = 0, gpuMsMax = 0; // AO + denoise: median, min, max over timed frames
    ErrorMetrics error;        // of the image judged: after temporal accumulation when it is on
    double rmseFirstFrame = 0; // geometry RMSE of the first frame alone (= error.rmse without temporal)
    int frames = 1;            // frames blended into the judged image
    // The baseline's median on this view, measured by the same run (NaN: take the baseline's row
    // of the same scene and viewpoint), and gpuMs / it.
    double baselineMs = std::numeric_limits<double>::quiet_NaN();
    double timeRatio = std::numeric_limits<double>::quiet_NaN(); // set by summarize()
    int shard = 0; // which run measured it (index into the report's shards; 0 unsharded)
    // The error split (reference_ao.h, ReferenceVisibility::Screen): the AO against the screen-space
    // oracle - what settings can still fix - and the oracle against the truth - what the screen does
    // not hold, the same for every configuration of a view. Without an oracle, hasSplit is false.
    bool hasSplit = false;
    ErrorMetrics vsOracle, screen;
    // The error by place (error_places.h) of the judged image; hasPlaces false for rows measured
    // without it (web engines, runs before it was kept).
    bool hasPlaces = false;
    ErrorByPlace places;
    bool hasMotion = false; // bench --motion measured this row along its view's camera path
    MotionSummary motion;
};

// RMS over views of a split's RMSE, and its edge/interior parts (NaN when no view has a split).
struct SplitSummary {
    double rmse = 0, bias = 0, rmseEdge = 0, rmseInterior = 0;
};

struct ConfigSummary {
    size_t config = 0;
    int views = 0;
    double gpuMs = 0, gpuMsMin = 0, gpuMsMax = 0;  // mean of the views' medians; min of mins; max of maxes
    // Views whose slowest timed frame took more than kUnsureTimeSpread x their median: a time that
    // varied that much is flagged wherever it is shown (one slow frame can reorder two rows).
    int unsureTimeViews = 0;
    PassTimes passMs;                               // mean of the views' medians
    double rmse = 0, mae = 0, bias = 0;            // RMSE = sqrt(mean of the views' MSE)
    double psnrGeometrySrgb = 0, psnrFullSrgb = 0; // 10 log10(1 / mean MSE) over views
    double rmseEdge = 0, rmseInterior = 0;         // RMS over the views that have such pixels
    double ssim = 0;
    double rmseFirstFrame = 0; // sqrt of the mean over views of the first frame's MSE
    long nonFinite = 0;
    // To the baseline: time = geometric mean over views of each row's ratio; error = RMSE / RMSE.
    double timeRatio = 0, rmseRatio = 0;
    // The motion score (motion_metrics.h's motionScore of the RMS motion RMSE and instability) and its
    // ratio to the baseline's; NaN without motion rows.
    double motionScore = std::numeric_limits<double>::quiet_NaN(), motionRatio = std::numeric_limits<double>::quiet_NaN();
    bool pareto = false; // on the front of (timeRatio, the objective's error)
    SplitSummary technique, screen; // the AO against the oracle; the oracle against the truth
    MotionSummary motion;           // over the views measured in motion (NaN: none)
};

constexpr double kUnsureTimeSpread = 2.0;

// What a benchmark ranks by (bench --objective): the still frame's geometry RMSE, or the motion score
// along each view's camera path. It decides the front, the answers and "fastest at most the baseline's".
enum class Objective { Still, Motion };
const char* objectiveKey(Objective o); // "still" / "motion"
// "still" or "motion"; anything else throws std::invalid_argument.
Objective parseObjective(const std::string& key);
// "RMSE" / "motion score": the error's name in an answer.
const char* objectiveErrorName(Objective o);
// "the still frame's RMSE" / "the motion score": what the front is drawn against.
const char* objectiveTitle(Objective o);
// "on a still camera" / "in motion": what an answer holds for.
const char* objectiveWhere(Objective o);
// The error a configuration is ranked by, and its ratio to the baseline's (NaN: not measured).
double objectiveError(const ConfigSummary& s, Objective o);
double objectiveRatio(const ConfigSummary& s, Objective o);

double median(std::vector<double> v); // NaN when empty

// true for every point not dominated by another (another point at most as slow and at most as
// wrong, strictly better in one). Minimises both coordinates; ties keep both.
std::vector<bool> paretoFront(const std::vector<double>& time, const std::vector<double>& error);

// One summary per configuration 0..configCount-1 (in that order), ratios against `baseline`, the
// front of time against the objective's error; fills each view's timeRatio.
std::vector<ConfigSummary> summarize(std::vector<ViewResult>& views, size_t configCount, size_t baseline,
                                     Objective objective = Objective::Still);

} // namespace ssao
