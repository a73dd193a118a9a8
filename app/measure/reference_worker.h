// Traces the ray-traced reference AO of one view on a background thread, progressively: batches of
// rays per pixel (4, 4, 8, 16, 32, then 64 at a time) up to the target, publishing the estimate
// after each. A new job cancels the running one. The Embree BVH is built on the worker thread, once
// per scene. No GL here: the UI thread takes the snapshots and uploads them.
#pragma once
#include "reference/reference_ao.h"
#include "scene/scene.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

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
    ~ReferenceWorker(); // cancels the job and joins the thread
    ReferenceWorker(const ReferenceWorker&) = delete;
    ReferenceWorker& operator=(const ReferenceWorker&) = delete;

    // Cancels the running job (if any) and queues this one; returns its id (ids start at 1).
    uint64_t start(Job job);
    // Cancels the running or queued job; returns at once (the thread stops at its next row).
    void cancel();

    Snapshot latest() const;
    Progress progress() const;
    // True while the thread works on a job (a cancelled one included, until it stops at a row).
    bool running() const { return running_.load(); }
    // Changes whenever a snapshot or the progress changes (cheap to poll every frame).
    uint64_t serial() const { return serial_.load(); }

    // Rays per pixel traced by each batch, in order, for a target of `target`.
    static std::vector<int> batches(int target);

  private:
    void run();
    void trace(const Job& job, uint64_t id);
    void setProgress(uint64_t id, const std::function<void(Progress&)>& change);

    std::function<void()> wake_;
    mutable std::mutex m_;
    std::condition_variable cv_;
    std::optional<Job> pending_;
    uint64_t pendingId_ = 0, lastId_ = 0;
    bool quit_ = false;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> running_{false};
    std::atomic<uint64_t> serial_{0};
    Snapshot snapshot_;
    Progress progress_;
    // Worker thread only: the BVH of the last scene traced, and that scene.
    std::shared_ptr<const Scene> bvhScene_;
    std::unique_ptr<EmbreeScene> bvh_;
    std::thread thread_; // last: started once everything above exists
};

} // namespace ssao
