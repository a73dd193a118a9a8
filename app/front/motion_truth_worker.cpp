#include "front/motion_truth_worker.h"

#include "measure/reference_worker.h"

namespace ssao {

MotionTruthWorker::MotionTruthWorker(std::function<void()> wake)
    : jobs_([this](const Job& job) { trace(job); }, std::move(wake)) {}

void MotionTruthWorker::trace(const Job& job) {
    lowerThisThreadsPriority(); // the frames first: it traces on the CPU time they leave
    auto publish = [&](const std::function<void(State&)>& change) { jobs_.publish(job, change); };
    try {
        if (providerScene_ != job.scene || providerDir_ != job.cacheDir) {
            provider_ = std::make_unique<ReferenceProvider>(*job.scene, job.cacheDir);
            providerScene_ = job.scene, providerDir_ = job.cacheDir;
        }
        auto truth = std::make_shared<MotionTruth>(traceMotionTruth(
            *provider_, job.scene->bounds, job.start, job.width, job.height, job.spec, job.settings,
            [&](double f) { publish([f](State& s) { s.fraction = f; }); }, &jobs_.cancelled()));
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
