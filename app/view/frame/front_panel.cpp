#include "view/frame/front_panel.h"

#include "metrics/bench_summary.h"
#include "settings/params.h"

#include <cmath>
#include <cstdio>
#include <tuple>

namespace ssao {

std::string FrontPanel::tunedDir(const PresetStore& store) {
    return store.userDir() + "/engines";
}

void FrontPanel::update(const Settings& current, const PresetStore& store, FrameDriver& frames,
                        const std::shared_ptr<const Scene>& scene, const std::string& sceneFile, double budgetMs) {
    frames.takeNews(); // before the engines' state is read: a result after it wakes the next frame
    if (!active || paused) return;
    const LiveReference& live = frames.reference();
    const auto ref = live.finished();
    if (!ref || !live.key() || frames.interacting()) {
        // The view changed (or is changing): what was measured is of another view.
        if (m_.busy()) m_.cancel();
        if (motion_.hasView()) motion_.cancel();
        engines_.cancel();
        const LiveReference::Status st = live.status();
        char b[96];
        std::snprintf(b, sizeof b, "waiting for the reference of this view (%.0f%%)", 100.0 * st.fraction);
        waiting_ = !frames.referenceOn ? "the reference is off (Reference tab): nothing to measure against"
                   : st.state == LiveReference::State::Failed ? "the reference failed: " + st.error
                                                              : std::string(b);
        compose();
        return;
    }
    waiting_.clear();
    const float radius = live.status().radius;
    // Candidates follow the current settings and R; built (presets read) only when those change.
    const std::string key = toEffectiveJson(current).dump() + "|" + std::to_string(radius);
    if (key != candidatesKey_) {
        candidates_ = frontCandidates(current, store, radius);
        candidatesKey_ = key;
    }
    FrontView v;
    v.scene = scene;
    v.sceneVersion = frames.renderer().sceneVersion();
    v.camera = live.key()->camera;
    v.width = live.key()->width;
    v.height = live.key()->height;
    v.radius = radius;
    v.reference = ref;
    m_.request(v, candidates_);
    updateMotion(frames, scene, v.sceneVersion);
    // The still measurement first (it gives every point its time), then the motion scores.
    if (m_.busy())
        m_.work(budgetMs);
    else if (motion_.measuring())
        motion_.work(budgetMs);
    else if (motion_.hasView())
        motion_.work(0.0); // takes the path's references once traced
    if (m_.busy() || motion_.measuring()) frames.keepAwake(); // the loop must not sleep while work is left
    // The engines after ssaolab's own candidates: the browser and the timed frames share the CPU.
    if (!m_.busy()) engines_.request(v, sceneFile, tunedDir(store));
    engines_.poll();
    compose();
}

void FrontPanel::updateMotion(const FrameDriver& frames, const std::shared_ptr<const Scene>& scene,
                              unsigned sceneVersion) {
    if (axis != Axis::Motion) {
        if (motion_.hasView()) motion_.cancel(); // its cache keeps what was scored
        return;
    }
    const LiveReference& live = frames.reference();
    MotionView mv;
    mv.scene = scene;
    mv.sceneVersion = sceneVersion;
    mv.camera = live.key()->camera;
    std::tie(mv.width, mv.height) = motionSize(live.key()->width, live.key()->height, motionMaxWidth, motionMaxHeight);
    mv.spec = motionPath;
    mv.settings.radius = live.status().radius;
    mv.settings.samples = live.finished()->samples; // the still reference's rays
    mv.settings.variant = ReferenceVariant::Visibility;
    mv.cacheDir = motionCacheDir;
    motion_.request(mv, candidates_);
}

void FrontPanel::compose() {
    points_.clear();
    for (const FrontPoint& p : m_.points()) {
        FrontPoint q = p;
        if (axis == Axis::Motion) {
            const MotionMetrics* mm = motion_.find(p.candidate);
            if (!mm) continue;
            q.motion = *mm;
            q.score = motionScore(*mm);
        } else {
            q.score = p.result.error.rmse;
        }
        points_.push_back(std::move(q));
    }
    if (axis == Axis::Still) // an engine's frame is scored still; it has no motion score
        for (FrontPoint& p : engines_.points())
            points_.push_back(std::move(p));
    size_t b = std::string::npos;
    for (size_t i = 0; i < points_.size(); ++i)
        if (points_[i].candidate.baseline) b = i;
    std::vector<double> t, e;
    for (auto& p : points_) {
        p.scoreRatio = b != std::string::npos ? p.score / points_[b].score : 0.0;
        if (p.candidate.isEngine() && b != std::string::npos) {
            p.timeRatio = p.result.gpuMs / points_[b].result.gpuMs;
            p.rmseRatio = p.result.error.rmse / points_[b].result.error.rmse;
        }
        t.push_back(p.result.gpuMs), e.push_back(p.score);
    }
    const std::vector<bool> f = paretoFront(t, e);
    for (size_t i = 0; i < points_.size(); ++i)
        points_[i].front = f[i];
}

std::string FrontPanel::axisName() const {
    return axis == Axis::Motion ? "motion score sqrt(RMSE^2 + instability^2)" : "RMSE";
}

size_t FrontPanel::currentIndex() const {
    for (size_t i = 0; i < points().size(); ++i)
        if (points()[i].candidate.current) return i;
    return std::string::npos;
}

size_t FrontPanel::baselineIndex() const {
    for (size_t i = 0; i < points().size(); ++i)
        if (points()[i].candidate.baseline) return i;
    return std::string::npos;
}

size_t FrontPanel::cheapestAtMostCurrentError() const {
    const size_t c = currentIndex();
    if (c == std::string::npos) return c;
    const auto& p = points();
    size_t best = std::string::npos;
    for (size_t i = 0; i < p.size(); ++i)
        if (i != c && !p[i].candidate.isEngine() && p[i].score <= p[c].score &&
            (best == std::string::npos || p[i].result.gpuMs < p[best].result.gpuMs))
            best = i;
    return best;
}

size_t FrontPanel::mostAccurateWithinCurrentTime() const {
    const size_t c = currentIndex();
    if (c == std::string::npos) return c;
    const auto& p = points();
    size_t best = std::string::npos;
    for (size_t i = 0; i < p.size(); ++i)
        if (i != c && !p[i].candidate.isEngine() && p[i].result.gpuMs <= p[c].result.gpuMs &&
            (best == std::string::npos || p[i].score < p[best].score))
            best = i;
    return best;
}

size_t FrontPanel::bestForBudget() const {
    if (!(budgetMs > 0) && !(maxError > 0)) return std::string::npos;
    const auto& p = points();
    size_t best = std::string::npos;
    for (size_t i = 0; i < p.size(); ++i) {
        const ViewResult& r = p[i].result;
        if (p[i].candidate.isEngine()) continue; // an answer is applied
        if ((budgetMs > 0 && !(r.gpuMs <= budgetMs)) || (maxError > 0 && !(p[i].score <= maxError))) continue;
        if (best == std::string::npos) {
            best = i;
            continue;
        }
        // A time budget asks for accuracy; an error bound alone asks for speed (as bench --budget-ms).
        if (budgetMs > 0 ? p[i].score < p[best].score : r.gpuMs < p[best].result.gpuMs) best = i;
    }
    return best;
}

double FrontPanel::referenceNoise() const {
    // The still reference's floor; the motion score has no band of its own.
    if (axis == Axis::Motion) return 0.0;
    return points().empty() ? 0.0 : points()[0].result.error.referenceNoise;
}

} // namespace ssao
