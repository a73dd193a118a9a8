// Traces the ray-traced reference AO of one view on a background thread, progressively: batches of
// rays per pixel (4, 4, 8, 16, 32, then 64 at a time) up to the target, publishing the estimate
// after each. A new job cancels the running one (measure/latest_job.h runs it). The Embree BVH is
// built on the worker thread, once per scene. No GL here: the UI thread takes the snapshots and
// uploads them.
#pragma once
#include "measure/latest_job.h"
#include "reference/reference_ao.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

// Puts the calling thread, and so the threads it starts, under the idle scheduling policy: it runs
// only on CPU time the frames leave (reference_worker.cpp).
void lowerThisThreadsPriority();

class ReferenceWorker {
  public:
    struct Job {
        std::shared_ptr<const Scene> scene; // kept alive while the BVH refers to it
        Camera camera;                      // as rendered (fitted clip planes)
        int width = 0, height = 0;          // the full render size, not the reduced one while moving
        ReferenceSettings settings;         // samples = the target rays per pixel
    };
    enum class Phase { Idle, Building, Tracing, Done, Failed };
    // Where the current job is; `job` is the id start() returned.
    struct Progress {
        uint64_t job = 0;
        Phase phase = Phase::Idle;
        int samples = 0;     // rays per pixel in the latest snapshot
        int target = 0;      // rays per pixel the job traces to
        double fraction = 0; // of the target, the batch in flight included
        std::string error;   // when Failed
    };
    struct Snapshot {
        uint64_t job = 0;
        std::shared_ptr<const ReferenceImage> image; // null until the first batch is done
    };

    // `wake` (may be empty) is called from the worker thread after each snapshot and progress step
    // (about five times a second): the window loop sleeps until an event, and this is one.
    explicit ReferenceWorker(std::function<void()> wake = {});
    ReferenceWorker(const ReferenceWorker&) = delete;
    ReferenceWorker& operator=(const ReferenceWorker&) = delete;

    // Cancels the running job (if any) and queues this one; returns its id (ids start at 1).
    uint64_t start(Job job);
    // Cancels the running or queued job; returns at once (the thread stops at its next row).
    void cancel() { jobs_.cancel(); }

    Snapshot latest() const { return jobs_.state().snapshot; }
    Progress progress() const { return jobs_.state().progress; }
    // True while the thread works on a job (a cancelled one included, until it stops at a row).
    bool running() const { return jobs_.running(); }
    // Changes whenever a snapshot or the progress changes (cheap to poll every frame).
    uint64_t serial() const { return jobs_.version(); }

    // Rays per pixel traced by each batch, in order, for a target of `target`.
    static std::vector<int> batches(int target);

  private:
    struct Queued {
        std::string key; // the id as text: every job a new one
        Job job;
        uint64_t id;
    };
    struct State {
        std::string key;
        unsigned version = 0;
        Progress progress;
        Snapshot snapshot;
    };
    void trace(const Queued& q);
    void setProgress(const Queued& q, const std::function<void(Progress&)>& change);

    uint64_t lastId_ = 0; // start()'s caller's thread only
    // Worker thread only: the BVH of the last scene traced, and that scene.
    std::shared_ptr<const Scene> bvhScene_;
    std::unique_ptr<EmbreeScene> bvh_;
    LatestJob<Queued, State> jobs_; // last: its thread uses the members above
};

} // namespace ssao
