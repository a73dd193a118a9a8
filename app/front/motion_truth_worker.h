// Traces the Front tab's motion truth (measure/motion_measure.h: a reference per frame of the camera
// path through the view, and the pixels followed between frames) on a background thread: the
// references and the reprojection need no GL. References come from and go to the disk cache, so a
// view's path is traced once across sessions. A new job cancels the running one between frames.
#pragma once
#include "measure/motion_measure.h"

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace ssao {

class MotionTruthWorker {
  public:
    struct Job {
        std::string key; // what the truth is of (front_motion.h); a job with the running key is a no-op
        std::shared_ptr<const Scene> scene;
        Camera start; // the view's camera; the path starts there
        int width = 0, height = 0;
        CameraPathSpec spec;
        ReferenceSettings settings;
        std::string cacheDir; // "" = no disk cache
    };
    struct State {
        std::string key;                          // of the job started last ("" none)
        double fraction = 0;                      // of the path traced
        std::shared_ptr<const MotionTruth> truth; // once done
        std::string error;                        // when the trace failed
    };

    // `wake` (may be empty) is called from the worker thread on progress and when done.
    explicit MotionTruthWorker(std::function<void()> wake = {});
    ~MotionTruthWorker(); // cancels the job and joins the thread
    MotionTruthWorker(const MotionTruthWorker&) = delete;
    MotionTruthWorker& operator=(const MotionTruthWorker&) = delete;

    void start(Job job);
    void cancel(); // forgets the job (the thread stops at the next path frame)
    State state() const;

  private:
    void run();
    void trace(const Job& job);

    std::function<void()> wake_;
    mutable std::mutex m_;
    std::condition_variable cv_;
    std::optional<Job> pending_;
    State state_;
    bool quit_ = false;
    std::atomic<bool> cancel_{false};
    // Worker thread only: the provider (its BVH) of the last scene traced, and that scene.
    std::shared_ptr<const Scene> providerScene_;
    std::string providerDir_;
    std::unique_ptr<ReferenceProvider> provider_;
    std::thread thread_; // last: started once everything above exists
};

} // namespace ssao
