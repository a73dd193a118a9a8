// Judges an AO frame against a reference snapshot (metrics/evaluate.h) on its own thread: the
// metrics of a full-size frame (SSIM, edge mask, percentiles) take longer than a UI frame may.
// One request at a time; a newer request replaces one still queued.
#pragma once
#include "metrics/evaluate.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace ssao {

class ErrorEvaluator {
  public:
    struct Request {
        Image ao; // read back on the GL thread
        std::shared_ptr<const ReferenceImage> reference;
        uint64_t tag = 0; // the caller's, returned with the result
        // The view's screen-space oracle, when traced: the frame is judged against it too (the
        // technique's share of the error) and it against the reference (the screen's share).
        std::shared_ptr<const ReferenceImage> oracle;
        // Chain B's ao.denoised in the split view (empty: none, or B shares A's): judged the same way.
        Image aoB;
        // The camera the reference traced and its R (scene units): the error by place (error_places.h);
        // R 0: none.
        Camera camera;
        double radius = 0;
    };
    struct Result {
        Evaluation evaluation;
        std::shared_ptr<const ReferenceImage> reference;
        uint64_t tag = 0;
        std::shared_ptr<const ReferenceImage> oracle;
        std::optional<ErrorMetrics> technique, screen; // with an oracle
        std::optional<ErrorShares> shares;             // with an oracle: the parts that add up
        std::optional<ErrorMetrics> metricsB;          // of Request::aoB, when given
        std::optional<ErrorByPlace> places;            // with Request::radius: where the error lives
    };

    // `wake` (may be empty) is called from the evaluator's thread when a result is ready.
    explicit ErrorEvaluator(std::function<void()> wake = {});
    ~ErrorEvaluator(); // finishes the evaluation under way (if any) and joins
    ErrorEvaluator(const ErrorEvaluator&) = delete;
    ErrorEvaluator& operator=(const ErrorEvaluator&) = delete;

    void submit(Request r);
    // The latest finished result, once; nullopt when none is new.
    std::optional<Result> take();
    // True while a request is queued or being evaluated.
    bool busy() const;
    // Changes whenever a result is ready (cheap to poll every frame).
    uint64_t serial() const { return serial_.load(); }

  private:
    void run();

    std::function<void()> wake_;
    mutable std::mutex m_;
    std::condition_variable cv_;
    std::optional<Request> pending_;
    std::optional<Result> result_;
    bool working_ = false, quit_ = false;
    std::atomic<uint64_t> serial_{0};
    // The last reference's places (evaluator thread only).
    PlaceMap places_;
    std::shared_ptr<const ReferenceImage> placesOf_;
    double placesRadius_ = 0;
    Camera placesCamera_;
    std::thread thread_; // last: started once everything above exists
};

} // namespace ssao
