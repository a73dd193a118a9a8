// Runs the Front tab's engine candidates (front/engine_candidates.h) on a background thread: each
// engine in Chromium through engines/engine_runner.h (Node.js and a browser: seconds per engine,
// never on the UI thread) at the view's camera, size and R, its AO scored in-process against the
// view's finished reference with metrics/evaluate.h, as `tune --engine` and `bench --engines`
// score it: one browser session per engine (its defaults and its tuned fits). A new job cancels
// the running one between sessions (a session is not interrupted).
#pragma once
#include "base/image.h"
#include "engines/engine_runner.h"
#include "front/engine_candidates.h"
#include "measure/latest_job.h"
#include "metrics/error_metrics.h"
#include "reference/reference_ao.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

// One engine candidate measured on one view.
struct EngineSample {
    EngineCandidate candidate;
    std::string title;                    // the table's ("N8AO (N8AOPass)")
    Image ao;                             // 1 channel, [0, 1], top row first, the view's size
    Image shown;                          // ao as the explorer paints AO: sky (no geometry) grey
    ErrorMetrics error;                   // against the view's reference
    double aoMs = std::numeric_limits<double>::quiet_NaN(); // frame with the pass - frame without
    std::map<std::string, double> values; // what the pass ran with (every row but the fixed ones)
    std::string snippet;                  // those settings as JavaScript for the engine's API
};

class EngineWorker {
  public:
    struct Job {
        std::string key; // what it is of (view and candidates); a job with the running key is a no-op
        std::string sceneFile, sceneName;
        nlohmann::json camera; // metrics.json's camera: the file's coordinates, fitted clip planes
        float radius = 0;      // R, scene units
        int width = 0, height = 0;
        std::shared_ptr<const ReferenceImage> reference;
        std::vector<EngineCandidate> candidates;
        std::string modules; // the npm packages ("" = the build folder's)
        int frames = 5;      // timed frames (median) per candidate
    };
    struct State {
        std::string key;   // of the job started last ("" none)
        size_t total = 0;  // candidates of that job
        std::vector<std::shared_ptr<const EngineSample>> samples;
        std::string running;     // the engine in the browser now
        bool done = false;
        std::string toolsError;  // Node.js, the browser or a package missing: no engine can run
        std::vector<std::string> errors; // engines that failed on this view, one line each
        unsigned version = 0;    // changes with every publication
    };

    // `wake` (may be empty) is called from the worker thread whenever the state changes.
    explicit EngineWorker(std::function<void()> wake = {});
    EngineWorker(const EngineWorker&) = delete;
    EngineWorker& operator=(const EngineWorker&) = delete;

    void start(Job job);
    void cancel() { jobs_.cancel(); } // forgets the job (its session under way ends, its results are dropped)
    State state() const { return jobs_.state(); }

  private:
    void measure(const Job& job);
    bool publish(const Job& job, const std::function<void(State&)>& change) { return jobs_.publish(job, change); }
    // One engine's candidates of the job (all of one table), in one browser session.
    void measureEngine(const Job& job, const std::vector<const EngineCandidate*>& cands, const EngineTable& t,
                       const EngineTools& tools);

    // Last: destroyed first, so its thread ends (waiting for a session under way) before the rest.
    LatestJob<Job, State> jobs_;
};

// The line locateEngineTools throws, without the command it names ("tune --engine n8ao runs N8AO
// (N8AOPass) in Chromium: ") : what is missing and how to install it.
std::string engineToolsReason(const std::string& message);

} // namespace ssao
