#include "measure/reference_worker.h"

#include <algorithm>

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace ssao {

// The background work (the tracer, the error metrics) runs under Linux's SCHED_IDLE policy: it
// gets the CPU time no normal thread wants, so on a few cores (llvmpipe renders with the same
// CPUs) a frame keeps its time and the reference takes what is left. A thread's policy is its own
// and the threads it starts inherit it, so the tracer's row threads run under it too.
// Not a nice value: even nice 10 keeps a weight (110 against 1 024), so the tracer's threads
// would still take CPU from a frame. Where the policy is refused, nice 19 (weight 15) is next best.
void lowerThisThreadsPriority() {
#ifdef __linux__
    sched_param none{};
    none.sched_priority = 0; // the only priority SCHED_IDLE takes
    if (sched_setscheduler(0, SCHED_IDLE, &none) != 0) setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 19);
#endif
}

std::vector<int> ReferenceWorker::batches(int target) {
    // Small batches first so a usable picture appears within a frame or two; then doubling (each
    // snapshot halves the noise variance); capped at 64 so a snapshot still arrives every few
    // seconds at full size.
    std::vector<int> out;
    int done = 0, next = 4;
    while (done < target) {
        const int n = std::min(next, target - done);
        out.push_back(n);
        done += n;
        next = std::min(std::max(done, 4), 64);
    }
    return out;
}

ReferenceWorker::ReferenceWorker(std::function<void()> wake) : wake_(std::move(wake)) {
    thread_ = std::thread([this] { run(); });
}

ReferenceWorker::~ReferenceWorker() {
    {
        std::lock_guard<std::mutex> lock(m_);
        quit_ = true;
        pending_.reset();
        cancel_ = true;
    }
    cv_.notify_all();
    thread_.join();
}

uint64_t ReferenceWorker::start(Job job) {
    uint64_t id;
    {
        std::lock_guard<std::mutex> lock(m_);
        id = ++lastId_;
        pending_ = std::move(job);
        pendingId_ = id;
        cancel_ = true; // the running job stops at its next row; run() clears this for the new one
        progress_ = Progress{id, Phase::Building, 0, pending_->settings.samples, 0.0, {}};
        snapshot_ = Snapshot{id, nullptr};
    }
    ++serial_;
    cv_.notify_all();
    return id;
}

void ReferenceWorker::cancel() {
    {
        std::lock_guard<std::mutex> lock(m_);
        pending_.reset();
        cancel_ = true;
        progress_ = Progress{};
        snapshot_ = Snapshot{};
    }
    ++serial_;
}

ReferenceWorker::Snapshot ReferenceWorker::latest() const {
    std::lock_guard<std::mutex> lock(m_);
    return snapshot_;
}

ReferenceWorker::Progress ReferenceWorker::progress() const {
    std::lock_guard<std::mutex> lock(m_);
    return progress_;
}

void ReferenceWorker::setProgress(uint64_t id, const std::function<void(Progress&)>& change) {
    {
        std::lock_guard<std::mutex> lock(m_);
        if (progress_.job != id) return; // cancelled or superseded meanwhile: not ours to report
        change(progress_);
    }
    ++serial_;
    if (wake_) wake_();
}

void ReferenceWorker::run() {
    lowerThisThreadsPriority();
    std::unique_lock<std::mutex> lock(m_);
    for (;;) {
        cv_.wait(lock, [&] { return quit_ || pending_.has_value(); });
        if (quit_) return;
        const Job job = std::move(*pending_);
        const uint64_t id = pendingId_;
        pending_.reset();
        cancel_ = false; // under the lock: a start() after this point cancels this job again
        running_ = true;
        lock.unlock();
        trace(job, id);
        lock.lock();
        running_ = false;
    }
}

void ReferenceWorker::trace(const Job& job, uint64_t id) {
    try {
        if (job.scene != bvhScene_) {
            bvh_.reset(); // before its scene goes
            bvhScene_ = job.scene;
            bvh_ = std::make_unique<EmbreeScene>(*bvhScene_);
        }
        if (cancel_) return;
        ReferenceTracer tracer(*bvh_, job.camera, job.width, job.height, job.settings); // primary rays
        const int target = job.settings.samples;
        setProgress(id, [](Progress& p) { p.phase = Phase::Tracing; });
        int done = 0;
        for (const int n : batches(target)) {
            const auto onProgress = [&](double f) {
                setProgress(id, [&](Progress& p) { p.fraction = (double(done) + f * n) / double(target); });
            };
            if (!tracer.addSamples(n, &cancel_, onProgress)) return; // cancelled: the tracer is spent
            done += n;
            auto image = std::make_shared<const ReferenceImage>(tracer.image());
            {
                std::lock_guard<std::mutex> lock(m_);
                if (progress_.job != id) return;
                snapshot_ = Snapshot{id, std::move(image)};
                progress_.samples = done;
                progress_.fraction = double(done) / double(target);
                if (done >= target) progress_.phase = Phase::Done;
            }
            ++serial_;
            if (wake_) wake_();
        }
    } catch (const std::exception& e) {
        // Embree failures (out of memory, a degenerate scene) end this job, not the app.
        const std::string what = e.what();
        setProgress(id, [&](Progress& p) { p.phase = Phase::Failed, p.error = what; });
    }
}

} // namespace ssao
