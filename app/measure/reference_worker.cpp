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

ReferenceWorker::ReferenceWorker(std::function<void()> wake)
    : jobs_([this](const Queued& q) { trace(q); }, std::move(wake)) {}

uint64_t ReferenceWorker::start(Job job) {
    const uint64_t id = ++lastId_;
    State fresh;
    fresh.progress = Progress{id, Phase::Building, 0, job.settings.samples, 0.0, {}};
    fresh.snapshot = Snapshot{id, nullptr};
    jobs_.start(Queued{std::to_string(id), std::move(job), id}, std::move(fresh));
    return id;
}

void ReferenceWorker::setProgress(const Queued& q, const std::function<void(Progress&)>& change) {
    jobs_.publish(q, [&](State& s) { change(s.progress); }); // cancelled or superseded: not ours to report
}

void ReferenceWorker::trace(const Queued& q) {
    lowerThisThreadsPriority(); // the tracer's row threads inherit it
    const Job& job = q.job;
    const std::atomic<bool>& cancel = jobs_.cancelled();
    try {
        if (job.scene != bvhScene_) {
            bvh_.reset(); // before its scene goes
            bvhScene_ = job.scene;
            bvh_ = std::make_unique<EmbreeScene>(*bvhScene_);
        }
        if (cancel) return;
        ReferenceTracer tracer(*bvh_, job.camera, job.width, job.height, job.settings); // primary rays
        const int target = job.settings.samples;
        setProgress(q, [](Progress& p) { p.phase = Phase::Tracing; });
        int done = 0;
        for (const int n : batches(target)) {
            const auto onProgress = [&](double f) {
                setProgress(q, [&](Progress& p) { p.fraction = (double(done) + f * n) / double(target); });
            };
            if (!tracer.addSamples(n, &cancel, onProgress)) return; // cancelled: the tracer is spent
            done += n;
            auto image = std::make_shared<const ReferenceImage>(tracer.image());
            const bool ours = jobs_.publish(q, [&](State& s) {
                s.snapshot = Snapshot{q.id, std::move(image)};
                s.progress.samples = done;
                s.progress.fraction = double(done) / double(target);
                if (done >= target) s.progress.phase = Phase::Done;
            });
            if (!ours) return; // cancelled or superseded
        }
    } catch (const std::exception& e) {
        // Embree failures (out of memory, a degenerate scene) end this job, not the app.
        const std::string what = e.what();
        setProgress(q, [&](Progress& p) { p.phase = Phase::Failed, p.error = what; });
    }
}

} // namespace ssao
