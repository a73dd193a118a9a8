#include "view/live/error_evaluator.h"

#include "measure/reference_worker.h"

namespace ssao {

ErrorEvaluator::ErrorEvaluator(std::function<void()> wake) : wake_(std::move(wake)) {
    thread_ = std::thread([this] { run(); });
}

ErrorEvaluator::~ErrorEvaluator() {
    {
        std::lock_guard<std::mutex> lock(m_);
        quit_ = true;
        pending_.reset();
    }
    cv_.notify_all();
    thread_.join();
}

void ErrorEvaluator::submit(Request r) {
    {
        std::lock_guard<std::mutex> lock(m_);
        pending_ = std::move(r);
    }
    cv_.notify_all();
}

std::optional<ErrorEvaluator::Result> ErrorEvaluator::take() {
    std::lock_guard<std::mutex> lock(m_);
    std::optional<Result> out = std::move(result_);
    result_.reset();
    return out;
}

bool ErrorEvaluator::busy() const {
    std::lock_guard<std::mutex> lock(m_);
    return working_ || pending_.has_value();
}

void ErrorEvaluator::run() {
    lowerThisThreadsPriority(); // as the tracer: the frames come first
    std::unique_lock<std::mutex> lock(m_);
    for (;;) {
        cv_.wait(lock, [&] { return quit_ || pending_.has_value(); });
        if (quit_) return;
        Request r = std::move(*pending_);
        pending_.reset();
        working_ = true;
        lock.unlock();
        Result out{evaluate(r.ao, *r.reference), std::move(r.reference), r.tag, std::move(r.oracle), {}, {}};
        if (!r.aoB.data.empty()) out.metricsB = evaluate(r.aoB, *out.reference).metrics;
        const bool sameSize = out.oracle && out.oracle->width == out.reference->width && out.oracle->height == out.reference->height;
        if (r.radius > 0) {
            // The places depend on the reference's view alone: kept while the AO changes under it.
            if (placesOf_ != out.reference || placesRadius_ != r.radius || !(placesCamera_ == r.camera)) {
                places_ = placesOf(*out.reference, r.camera, r.radius);
                placesOf_ = out.reference, placesRadius_ = r.radius, placesCamera_ = r.camera;
            }
            out.places = errorByPlace(out.evaluation, *out.reference, places_, sameSize ? out.oracle.get() : nullptr);
        }
        if (out.oracle) {
            const Evaluation technique = evaluate(r.ao, *out.oracle);
            out.technique = technique.metrics;
            const Image oracleImg{out.oracle->width, out.oracle->height, 1, out.oracle->ao};
            out.screen = evaluate(oracleImg, *out.reference).metrics;
            if (out.oracle->width == out.reference->width && out.oracle->height == out.reference->height)
                out.shares = splitShares(technique, *out.oracle, *out.reference);
        }
        lock.lock();
        working_ = false;
        result_ = std::move(out);
        lock.unlock();
        ++serial_;
        if (wake_) wake_();
        lock.lock();
    }
}

} // namespace ssao
