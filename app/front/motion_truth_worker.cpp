#include "front/motion_truth_worker.h"

#include "measure/reference_worker.h"

namespace ssao {

MotionTruthWorker::MotionTruthWorker(std::function<void()> wake)
    : wake_(std::move(wake)), thread_([this] { run(); }) {}

MotionTruthWorker::~MotionTruthWorker() {
    {
        std::lock_guard<std::mutex> lock(m_);
        quit_ = true;
        pending_.reset();
    }
    cancel_ = true;
    cv_.notify_all();
    thread_.join();
}

void MotionTruthWorker::start(Job job) {
    std::lock_guard<std::mutex> lock(m_);
    if (job.key == state_.key) return;
    cancel_ = true; // the running job, if any, stops at its next frame
    state_ = State{};
    state_.key = job.key;
    pending_ = std::move(job);
    cv_.notify_all();
}

void MotionTruthWorker::cancel() {
    std::lock_guard<std::mutex> lock(m_);
    cancel_ = true;
    pending_.reset();
    state_ = State{};
}

MotionTruthWorker::State MotionTruthWorker::state() const {
    std::lock_guard<std::mutex> lock(m_);
    return state_;
}

void MotionTruthWorker::run() {
    lowerThisThreadsPriority(); // the frames first: it traces on the CPU time they leave
    for (;;) {
        Job job;
        {
            std::unique_lock<std::mutex> lock(m_);
            cv_.wait(lock, [&] { return quit_ || pending_.has_value(); });
            if (quit_) return;
            job = std::move(*pending_);
            pending_.reset();
            cancel_ = false;
        }
        trace(job);
    }
}

void MotionTruthWorker::trace(const Job& job) {
    // Publishes into the state only while the job is still the one asked for.
    auto publish = [&](const std::function<void(State&)>& change) {
        {
            std::lock_guard<std::mutex> lock(m_);
            if (state_.key != job.key || cancel_) return;
            change(state_);
        }
        if (wake_) wake_();
    };
    try {
        if (providerScene_ != job.scene || providerDir_ != job.cacheDir) {
            provider_ = std::make_unique<ReferenceProvider>(*job.scene, job.cacheDir);
            providerScene_ = job.scene, providerDir_ = job.cacheDir;
        }
        auto truth = std::make_shared<MotionTruth>(traceMotionTruth(
            *provider_, job.scene->bounds, job.start, job.width, job.height, job.spec, job.settings,
            [&](double f) { publish([f](State& s) { s.fraction = f; }); }, &cancel_));
        publish([&](State& s) {
            s.fraction = 1.0;
            s.truth = std::move(truth);
        });
    } catch (const std::exception& e) {
        const std::string what = e.what();
        publish([&](State& s) { s.error = what; });
    }
}

} // namespace ssao
