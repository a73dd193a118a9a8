// The explorer's front panel measurement: every candidate (front/candidates.h) on the view on
// screen, its error against the finished live reference and its GPU time at the view's size, run
// in slices between the explorer's frames (one rendered frame per step, steps until a per-frame
// time budget is spent) with its own renderer, so the view on screen is never disturbed. The
// steps are bench's (measure/measurement.h): the panel and `bench` get the same numbers. Completed
// views are cached, so going back to a view shows its front at once.
#pragma once
#include "measure/measurement.h"
#include "front/candidates.h"
#include "metrics/motion_metrics.h"
#include "scene/scene.h"

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct FrontPoint {
    Candidate candidate;
    ViewResult result;
    double timeRatio = 0, rmseRatio = 0; // to the baseline candidate (once it is measured)
    bool front = false;                  // on the front of (time, score) of the points measured so far
    // The Front tab's y axis (front_panel.h): the RMSE, or on the motion axis the motion score.
    double score = 0, scoreRatio = 0;
    std::optional<MotionMetrics> motion; // on the motion axis
};

// What one measurement is of: a change of any of it cancels the one running.
struct FrontView {
    std::shared_ptr<const Scene> scene;
    unsigned sceneVersion = 0;
    Camera camera; // as the reference traced it (clip planes fitted)
    int width = 0, height = 0;
    float radius = 0; // world R of the reference
    std::shared_ptr<const ReferenceImage> reference;
    std::string key() const; // scene version, camera, size, radius, reference rays
};

class FrontMeasurer {
  public:
    explicit FrontMeasurer(std::string shaderDir, int warmup = 2, int frames = 5)
        : shaderDir_(std::move(shaderDir)), warmup_(warmup), frames_(frames) {}

    // Measures `candidates` on `view` (those not cached for it) unless that is what runs already.
    void request(const FrontView& view, std::vector<Candidate> candidates);
    void cancel(); // the view left: stop (the measured part is dropped)

    // Runs steps for about `budgetMs` of wall time, at least one (GL context current).
    void work(double budgetMs);
    bool busy() const { return !pending_.empty() || current_.has_value(); }

    struct Progress {
        size_t done = 0, total = 0;
        double fraction = 0;   // of the frames needed
        double etaSeconds = 0; // at the step time seen so far
        double seconds = 0;    // spent measuring this view so far
    };
    Progress progress() const;
    bool hasView() const { return !key_.empty(); }
    const std::vector<FrontPoint>& points() const { return points_; }
    // The candidate that comes first in both answers; npos when none (see front_panel.h).
    size_t baselineIndex() const;

  private:
    void finishCurrent();
    void updateFront();

    std::string shaderDir_;
    int warmup_, frames_;
    std::unique_ptr<Renderer> renderer_;
    std::shared_ptr<const Scene> uploaded_; // the scene renderer_ holds
    FrontView view_;
    std::string key_, viewKey_;
    std::vector<Candidate> pending_;
    std::optional<std::pair<Candidate, Measurement>> current_;
    std::vector<FrontPoint> points_;
    size_t total_ = 0;
    double secondsSpent_ = 0;
    int stepsDone_ = 0;
    // By view key, then by candidate settings: a view's points survive leaving it and coming back,
    // and a new current setting measures only itself and its neighbours.
    std::map<std::string, std::map<std::string, FrontPoint>> cache_;
};

} // namespace ssao
