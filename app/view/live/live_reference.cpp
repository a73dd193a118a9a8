#include "view/live/live_reference.h"
#include "gl/readback.h"

#include "base/image.h"

#include <algorithm>
#include <thread>

namespace ssao {

bool LiveReference::Key::operator==(const Key& o) const {
    const Camera &a = camera, &b = o.camera;
    return sceneVersion == o.sceneVersion && width == o.width && height == o.height && target == o.target &&
           a == b && radius.radiusMode == o.radius.radiusMode &&
           radius.radius == o.radius.radius && radius.radiusScene == o.radius.radiusScene &&
           radius.radiusPx == o.radius.radiusPx;
}

void LiveReference::forget() {
    snapshot_.reset();
    submitted_.reset();
    if (oracleStarted_) oracleWorker_.cancel();
    oracleStarted_ = false;
    oracle_.reset();
    submittedOracle_.reset();
    validFrom_ = tag_ + 1; // an evaluation under way is of the old view
    clear();
}

void LiveReference::clear() {
    shown_.reset();
    metrics_.reset();
    metricsB_.reset();
    split_.reset();
    places_.reset();
    // Bumped only when the buffers held something: while the camera moves this runs every frame,
    // and the upload pass must not run with it.
    if (!buffers_ || buffers_->width > 0) {
        auto b = std::make_shared<ReferenceBuffers>();
        b->version = ++version_;
        buffers_ = std::move(b);
    }
}

void LiveReference::publish(const ErrorEvaluator::Result& r) {
    shown_ = r.reference;
    auto b = std::make_shared<ReferenceBuffers>();
    b->width = shown_->width;
    b->height = shown_->height;
    b->ao = shown_->ao;
    b->error = r.evaluation.error.data;
    b->version = ++version_;
    buffers_ = std::move(b);
    metrics_ = r.evaluation.metrics;
    metricsB_ = r.metricsB;
    places_ = r.places;
    if (r.technique && r.screen)
        split_ = Split{*r.technique, *r.screen, r.shares.value_or(ErrorShares{})};
    else
        split_.reset();
}

double LiveReference::oracleFraction() const {
    if (!oracleStarted_) return 0.0;
    if (oracle_) return 1.0;
    const ReferenceWorker::Progress p = oracleWorker_.progress();
    return p.job == oracleJob_ ? std::min(p.fraction, 0.999) : 0.0;
}

// Starts the trace of the view just rendered.
void LiveReference::startTrace(const Renderer& r, const std::shared_ptr<const Scene>& scene, int targetRays,
                               int fullW, int fullH, const std::function<float()>& radiusWorld) {
    // The frame just rendered is the full-size one: its radius at the centre is the one shown.
    ReferenceWorker::Job job;
    job.scene = scene;
    job.camera = r.camera();
    job.width = fullW;
    job.height = fullH;
    job.settings.radius = radiusWorld();
    job.settings.samples = targetRays;
    job.settings.variant = ReferenceVariant::Visibility;
    // One core stays with the renderer (llvmpipe draws the frames on the CPU too).
    job.settings.threads = std::max(1, int(std::thread::hardware_concurrency()) - 1);
    radius_ = job.settings.radius;
    job_ = worker_.start(std::move(job));
    started_ = true;
}

// Once the reference is done: the oracle of the same view (same R, a quarter of the rays - 128
// of 512: its noise, about 0.02 RMS, only has to stay below the split's differences; it marches
// the screen per ray and costs about twice the reference per ray on the CPU), visibility from
// the depth layer alone; taken when it is done.
void LiveReference::followOracle(const std::shared_ptr<const Scene>& scene) {
    if (!oracleStarted_ && snapshot_ && snapshot_->samples >= key_->target) {
        ReferenceWorker::Job job;
        job.scene = scene;
        job.camera = key_->camera;
        job.width = key_->width;
        job.height = key_->height;
        job.settings.radius = radius_;
        job.settings.samples = std::max(16, key_->target / 4);
        job.settings.variant = ReferenceVariant::Visibility;
        job.settings.visibility = ReferenceVisibility::Screen;
        job.settings.threads = std::max(1, int(std::thread::hardware_concurrency()) - 1);
        oracleJob_ = oracleWorker_.start(std::move(job));
        oracleStarted_ = true;
    }
    if (oracleStarted_ && !oracle_) {
        ReferenceWorker::Snapshot o = oracleWorker_.latest();
        const ReferenceWorker::Progress op = oracleWorker_.progress();
        if (o.job == oracleJob_ && o.image && op.job == oracleJob_ && op.phase == ReferenceWorker::Phase::Done)
            oracle_ = std::move(o.image);
    }
}

// The error follows each new snapshot and ao.denoised (a parameter changed, the reference
// stays); the evaluation runs on the evaluator's thread and is shown when it is done.
void LiveReference::submitEvaluation(const Renderer& r) {
    const Resource* ao = r.graph().find("ao.denoised");
    // The split view's B, judged beside A when its AO is its own (AO on | off shares A's).
    const Resource* aoB = r.graph().resolve("b.ao.denoised") != r.graph().resolve("ao.denoised")
                              ? r.graph().find("b.ao.denoised")
                              : nullptr;
    const std::string bKey =
        aoB ? std::to_string(aoB->version) + "/" + std::to_string(aoB->generation) : std::string();
    if (snapshot_ && ao &&
        (snapshot_ != submitted_ || oracle_ != submittedOracle_ || ao->version != submittedAo_ ||
         ao->generation != submittedAoGeneration_ || bKey != submittedB_)) {
        evaluator_.submit({readBack(ao->texture, 1), snapshot_, ++tag_, oracle_, aoB ? readBack(aoB->texture, 1) : Image{},
                           key_ ? key_->camera : Camera{}, key_ ? radius_ : 0.0});
        submittedB_ = bKey;
        submitted_ = snapshot_;
        submittedOracle_ = oracle_;
        submittedAo_ = ao->version;
        submittedAoGeneration_ = ao->generation;
    }
}

bool LiveReference::update(Renderer& r, const std::shared_ptr<const Scene>& scene, bool on, int targetRays,
                           int fullW, int fullH, bool interacting,
                           const std::function<float()>& radiusWorld) {
    // Read first: whatever the threads do after this is news next time.
    seenTrace_ = worker_.serial();
    seenOracle_ = oracleWorker_.serial();
    seenEvaluation_ = evaluator_.serial();
    if (!on) {
        const bool had = key_ || buffers_;
        if (key_) worker_.cancel();
        key_.reset();
        started_ = false;
        forget();
        buffers_.reset();
        return had;
    }
    bool changed = !buffers_;
    const Key key{r.sceneVersion(), r.camera(), fullW, fullH, targetRays, r.settings().ao};
    if (!key_ || *key_ != key) {
        if (started_) worker_.cancel(); // the trace is of another view now
        key_ = key;
        started_ = false;
        const uint64_t before = buffers_ ? buffers_->version : 0;
        forget();
        changed |= buffers_->version != before;
    }
    // While input moves, the trace neither starts (dragging the camera would start and cancel one
    // per frame) nor shows its progress: the frames keep the CPU.
    if (interacting) return changed;
    if (!started_) startTrace(r, scene, targetRays, fullW, fullH, radiusWorld);
    ReferenceWorker::Snapshot s = worker_.latest();
    if (s.job == job_ && s.image) snapshot_ = std::move(s.image);
    followOracle(scene);
    submitEvaluation(r);
    if (std::optional<ErrorEvaluator::Result> done = evaluator_.take(); done && done->tag >= validFrom_) {
        publish(*done);
        changed = true;
    }
    return changed;
}

LiveReference::Status LiveReference::status() const {
    Status s;
    if (!key_) return s;
    s.target = key_->target;
    s.radius = radius_;
    if (!started_) {
        s.state = State::Waiting;
        return s;
    }
    const ReferenceWorker::Progress p = worker_.progress();
    s.fraction = p.job == job_ ? p.fraction : 0.0;
    s.rays = shown_ ? shown_->samples : 0;
    if (shown_) {
        s.seconds = shown_->seconds;
        s.mraysPerSecond = shown_->raysPerSecond() * 1e-6;
    }
    switch (p.phase) {
    case ReferenceWorker::Phase::Idle:
    case ReferenceWorker::Phase::Building:
        s.state = State::Starting;
        break;
    case ReferenceWorker::Phase::Tracing:
        s.state = State::Tracing;
        break;
    case ReferenceWorker::Phase::Done: // done only once the buffers show the last snapshot
        s.state = s.rays >= s.target ? State::Done : State::Tracing;
        break;
    case ReferenceWorker::Phase::Failed:
        s.state = State::Failed;
        s.error = p.error;
        break;
    }
    return s;
}

} // namespace ssao
