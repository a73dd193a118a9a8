// The ray-traced reference in the explorer: keeps a background trace of the view on screen
// (ReferenceWorker), restarts it when the camera, the radius, the size or the scene changes (never
// while the user is still moving), and judges the current ao.denoised against the latest estimate
// (ErrorEvaluator, off the UI thread too). What it produces, the renderer shows as the buffers
// reference.ao and reference.error.
#pragma once
#include "metrics/evaluate.h"
#include "passes/reference_pass.h"
#include "renderer.h"
#include "view/live/error_evaluator.h"
#include "measure/reference_worker.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace ssao {

class LiveReference {
  public:
    enum class State {
        Off,      // turned off: no trace, no buffers
        Waiting,  // the view changed and input has not settled: the trace waits (no thrashing)
        Starting, // BVH and primary rays
        Tracing,  // rays accumulating; the buffers show the latest snapshot
        Done,     // the target reached
        Failed,   // the tracer threw (message in error)
    };
    struct Status {
        State state = State::Off;
        int rays = 0;        // rays per pixel of the snapshot the buffers show
        int target = 0;      // rays per pixel the trace goes to
        double fraction = 0; // of the target traced so far, the batch in flight included
        double seconds = 0;  // tracing time of the snapshot shown
        double mraysPerSecond = 0;
        float radius = 0; // R of the trace, scene units
        std::string error;
    };
    // What the view depends on; a change cancels the trace.
    struct Key {
        unsigned sceneVersion = 0;
        Camera camera;
        int width = 0, height = 0;
        int target = 0;
        AoSettings radius; // only the radius fields are compared
        bool operator==(const Key& o) const;
        bool operator!=(const Key& o) const { return !(*this == o); }
    };

    explicit LiveReference(const std::function<void()>& wake = {})
        : worker_(wake), oracleWorker_(wake), evaluator_(wake) {}

    // Once per frame after the renderer rendered (GL context current). `scene` is what the
    // renderer shows, `fullW x fullH` the render size when input is still, `radiusWorld` the AO's
    // world radius at the centre of the view (only read when a trace starts). Returns true when
    // the buffers changed: render again to upload them. While `interacting` the buffers stay as
    // they are (or empty, when the view changed).
    bool update(Renderer& r, const std::shared_ptr<const Scene>& scene, bool on, int targetRays, int fullW,
                int fullH, bool interacting, const std::function<float()>& radiusWorld);

    // The buffers to hand to Renderer::setReferenceBuffers (null when off).
    const std::shared_ptr<const ReferenceBuffers>& buffers() const { return buffers_; }
    Status status() const;
    // The error of ao.denoised against the snapshot shown; nullopt before the first snapshot.
    const std::optional<ErrorMetrics>& metrics() const { return metrics_; }
    // The same of chain B's ao.denoised in the split view; nullopt without B or when B shares A's AO.
    const std::optional<ErrorMetrics>& metricsB() const { return metricsB_; }
    // Once the reference is done, the screen-space oracle of the view is traced (visibility from
    // the depth layer only, surfaces 1 R thick and MASK cut-outs sheets: the best any screen-space
    // technique could do) and the error splits: the technique (ao.denoised vs the oracle) and the
    // screen (the oracle vs the reference), with their shares of the squared error (error_split.h).
    // nullopt until both are known.
    struct Split {
        ErrorMetrics technique, screen;
        ErrorShares shares; // of the total squared error: technique + screen + interaction = 1
    };
    const std::optional<Split>& split() const { return split_; }
    // The error of ao.denoised by where its pixels are (metrics/error_places.h); nullopt before the
    // first evaluation.
    const std::optional<ErrorByPlace>& places() const { return places_; }
    // Where the oracle is: 0 not started, in (0, 1) tracing, 1 done.
    double oracleFraction() const;
    // The finished reference of the view (every ray traced), null while it is not; with the key it
    // traced (the camera as rendered, the size) and its world radius R.
    std::shared_ptr<const ReferenceImage> finished() const {
        return status().state == State::Done ? shown_ : nullptr;
    }
    const std::optional<Key>& key() const { return key_; }
    // True when the worker reported something this object has not yet looked at.
    bool hasNews() const {
        return worker_.serial() != seenTrace_ || oracleWorker_.serial() != seenOracle_ ||
               evaluator_.serial() != seenEvaluation_;
    }
    // True while the worker thread traces (a cancelled job until it stops).
    bool tracing() const { return worker_.running() || oracleWorker_.running(); }
    // True while an error evaluation is queued or running.
    bool evaluating() const { return evaluator_.busy(); }

  private:
    void forget(); // the view changed: nothing traced or evaluated so far is of it
    void clear();  // no reference of the current view: the buffers read 0
    void publish(const ErrorEvaluator::Result& r);
    void startTrace(const Renderer& r, const std::shared_ptr<const Scene>& scene, int targetRays, int fullW,
                    int fullH, const std::function<float()>& radiusWorld);
    void followOracle(const std::shared_ptr<const Scene>& scene); // starts it once the reference is done
    void submitEvaluation(const Renderer& r); // of a new snapshot, oracle or ao.denoised

    ReferenceWorker worker_;
    ReferenceWorker oracleWorker_;
    ErrorEvaluator evaluator_;
    std::optional<Key> key_; // of the job started, or waiting to start
    bool started_ = false;
    uint64_t job_ = 0;
    float radius_ = 0;
    std::shared_ptr<const ReferenceImage> snapshot_;  // the latest of the current job
    std::shared_ptr<const ReferenceImage> shown_;     // the one the buffers show
    std::shared_ptr<const ReferenceImage> submitted_; // the one last sent to the evaluator...
    uint64_t submittedAo_ = 0;                        // ...with this ao.denoised version
    unsigned submittedAoGeneration_ = 0;
    std::string submittedB_; // "version/generation" of B's ao.denoised sent with it ("" without B)
    uint64_t tag_ = 0, validFrom_ = 0; // evaluations tagged below validFrom_ are of an older view
    std::shared_ptr<const ReferenceBuffers> buffers_;
    std::optional<ErrorMetrics> metrics_;
    std::optional<ErrorMetrics> metricsB_;
    bool oracleStarted_ = false;
    uint64_t oracleJob_ = 0;
    std::shared_ptr<const ReferenceImage> oracle_;          // of the current view, once done
    std::shared_ptr<const ReferenceImage> submittedOracle_; // sent with the last request
    std::optional<Split> split_;
    std::optional<ErrorByPlace> places_;
    uint64_t version_ = 0;
    uint64_t seenTrace_ = 0, seenOracle_ = 0, seenEvaluation_ = 0;
};

} // namespace ssao
