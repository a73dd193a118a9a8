// Traces the Front tab's motion truth (measure/motion_measure.h: a reference per frame of the camera
// path through the view, and the pixels followed between frames) on a background thread: the
// references and the reprojection need no GL. References come from and go to the disk cache, so a
// view's path is traced once across sessions. A new job cancels the running one between frames.
#pragma once
#include "measure/latest_job.h"
#include "measure/motion_measure.h"

#include <functional>
#include <memory>
#include <string>

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
        unsigned version = 0;                     // changes with every publication
    };

    // `wake` (may be empty) is called from the worker thread on progress and when done.
    explicit MotionTruthWorker(std::function<void()> wake = {});
    MotionTruthWorker(const MotionTruthWorker&) = delete;
    MotionTruthWorker& operator=(const MotionTruthWorker&) = delete;

    void start(Job job) { jobs_.start(std::move(job)); } // the running job stops at its next path frame
    void cancel() { jobs_.cancel(); }                    // forgets the job
    State state() const { return jobs_.state(); }

  private:
    void trace(const Job& job);

    // Worker thread only: the provider (its BVH) of the last scene traced, and that scene.
    std::shared_ptr<const Scene> providerScene_;
    std::string providerDir_;
    std::unique_ptr<ReferenceProvider> provider_;
    LatestJob<Job, State> jobs_; // last: its thread uses the members above
};

} // namespace ssao
