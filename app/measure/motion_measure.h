// Error in motion, measured: the ray-traced truth along a camera path through a view (a cached
// reference per frame, and each frame's pixels followed into the frame before), and one
// configuration's frames along it as the explorer draws them - temporal accumulation, when the
// settings enable it, carries its history from frame to frame - judged by metrics/motion_metrics.h.
// `render --motion`, `bench --motion` and `tune --objective motion` share it.
#pragma once
#include "base/image.h"
#include "metrics/motion_metrics.h"
#include "reference/reference_cache.h"
#include "renderer.h"
#include "scene/camera_path.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

// --motion-frames, --motion-orbit, --motion-dolly, --motion-max-mib (render, bench, tune).
void addMotionPathOptions(CLI::App& cmd, CameraPathSpec& spec);

// What a path's frames keep at once, per pixel of a frame: the reference's five float images
// (AO, standard error, depth, geometry, ambiguity), the reprojection to the previous frame and the
// rendered AO. A run that keeps `truths` paths at once (tune keeps every view's) needs truths x
// frames x pixels x this.
constexpr size_t kMotionBytesPerPixelFrame = 5 * 4 + 4 + 4;
// Warnings for path options set away from their defaults in a run that has no path (`needs`: the
// option that makes one, "--motion" or "--objective motion"), as settings that do nothing are named.
std::vector<std::string> unusedMotionOptions(const CameraPathSpec& spec, const std::string& needs);

// Throws, before any work, one line naming what the paths would keep against spec.maxMib and the
// options that change it (--motion-frames, --size, --motion-max-mib).
void checkMotionBudget(const CameraPathSpec& spec, int width, int height, size_t truths);

struct MotionTruth {
    CameraPathSpec spec;
    int width = 0, height = 0;
    std::vector<Camera> path;     // the cameras set on the renderer
    std::vector<Camera> rendered; // as rendered (clip planes fitted): what the references trace
    std::vector<ReferenceImage> refs;
    std::vector<std::vector<int>> toPrevious; // metrics/reprojection.h; [0] is empty
    ReferenceSettings settings;
    int cached = 0;     // references that came from the cache
    double seconds = 0; // tracing time of the others
};

// The truth of the path from `start` (a camera as set: its clip planes are fitted to `bounds` as the
// renderer fits them). `progress` gets 0..1 over the whole path. A raised `cancel` is seen between
// frames (a frame's trace runs to its end and is cached): it throws ssao::Error.
// It checks its own budget first (checkMotionBudget of one path).
MotionTruth traceMotionTruth(ReferenceProvider& provider, const Bounds& bounds, const Camera& start, int width,
                             int height, const CameraPathSpec& spec, const ReferenceSettings& rs,
                             const std::function<void(double)>& progress = {},
                             const std::atomic<bool>* cancel = nullptr);

// Renders `s` along the truth's path on `r` (its scene and size those of the truth): the first frame
// as render and bench judge a still view (temporal accumulation, from an empty history, run to its
// end), then one frame per camera. Leaves `r` set to the path's first camera.
MotionMetrics measureMotion(Renderer& r, const Settings& s, const MotionTruth& truth);

// measureMotion one rendered frame per step, for the explorer's front panel between its frames.
// `r` is this measurement's alone from its first step to its last; `truth` outlives it.
class MotionMeasurement {
  public:
    MotionMeasurement(const Settings& s, const MotionTruth& truth) : settings_(s), truth_(&truth) {}
    bool step(Renderer& r); // true once done
    bool done() const { return done_; }
    double progress() const; // 0..1: path frames judged
    const MotionMetrics& result() const { return result_; }
    const Settings& settings() const { return settings_; }

  private:
    void finish(Renderer& r);

    Settings settings_;
    const MotionTruth* truth_;
    bool started_ = false, inFrame_ = false, done_ = false;
    size_t frame_ = 0; // the path frame being rendered
    std::vector<Image> tests_;
    MotionMetrics result_;
};

// metrics.json's "motion" block; NaN -> null.
nlohmann::json motionJson(const MotionMetrics& m, const MotionTruth& t);
// "motion (8 frames, ...): RMSE mean ..., instability ..., ghosting ..." (no newline).
std::string motionLine(const MotionMetrics& m, const MotionTruth& t);

} // namespace ssao
