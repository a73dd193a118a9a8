// The Front tab's motion axis: every candidate (front/candidates.h) scored along the camera path
// through the view on screen as `bench --motion` scores it (measure/motion_measure.h), at a reduced
// size (the path's references cost a frame's trace each). The path's references are traced in the
// background (front/motion_truth_worker.h); then each candidate renders one path frame per step
// on this object's own renderer, between the explorer's frames. Completed views are cached.
#pragma once
#include "measure/motion_measure.h"
#include "front/candidates.h"
#include "front/motion_truth_worker.h"

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ssao {

// What the motion scores are of: a change of any of it cancels the measurement.
struct MotionView {
    std::shared_ptr<const Scene> scene;
    unsigned sceneVersion = 0;
    Camera camera;             // the view's, where the path starts
    int width = 0, height = 0; // the reduced size (motionSize)
    CameraPathSpec spec;
    ReferenceSettings settings; // R and rays of the view's reference
    std::string cacheDir;       // of the references ("" = none)
    std::string key() const;
};

// w x h scaled down, aspect kept, to fit maxW x maxH (never up); at least 1 x 1.
std::pair<int, int> motionSize(int w, int h, int maxW, int maxH);

class FrontMotion {
  public:
    FrontMotion(std::string shaderDir, std::function<void()> wake = {})
        : shaderDir_(std::move(shaderDir)), worker_(std::move(wake)) {}

    // Scores `candidates` on `view` (those not cached for it) unless that is what runs already; the
    // path's references start tracing at once.
    void request(const MotionView& view, const std::vector<Candidate>& candidates);
    void cancel();
    // Once the references are in: steps for about `budgetMs`, at least one (GL context current).
    void work(double budgetMs);

    bool hasView() const { return !key_.empty(); }
    bool tracing() const; // the path's references are being traced
    bool measuring() const { return truth_ && (!pending_.empty() || current_.has_value()); }
    bool busy() const { return tracing() || measuring(); }

    struct Progress {
        double traceFraction = 0;   // of the path's references
        size_t done = 0, total = 0; // candidates scored
        double fraction = 0;        // of the candidates' path frames
        double seconds = 0;         // spent rendering them
        std::string error;          // the trace failed
    };
    Progress progress() const;
    // The candidate's motion metrics on the view requested; null until scored.
    const MotionMetrics* find(const Candidate& c) const;
    const std::shared_ptr<const MotionTruth>& truth() const { return truth_; }
    const MotionView& view() const { return view_; }

  private:
    std::string shaderDir_;
    MotionTruthWorker worker_;
    std::unique_ptr<Renderer> renderer_;
    std::shared_ptr<const Scene> uploaded_;
    MotionView view_;
    std::string key_, viewKey_;
    std::shared_ptr<const MotionTruth> truth_;
    std::vector<Candidate> pending_; // popped from the back
    std::optional<MotionMeasurement> current_;
    std::string currentKey_;
    size_t total_ = 0, done_ = 0;
    double secondsSpent_ = 0;
    // By view key, then by candidate settings.
    std::map<std::string, std::map<std::string, MotionMetrics>> cache_;
};

} // namespace ssao
