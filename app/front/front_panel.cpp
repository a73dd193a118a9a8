#include "front/front_panel.h"

#include "settings/params.h"

#include <cmath>
#include <cstdio>

namespace ssao {

void FrontPanel::update(const Settings& current, const PresetStore& store, FrameDriver& frames,
                        const std::shared_ptr<const Scene>& scene, double budgetMs) {
    if (!active || paused) return;
    const LiveReference& live = frames.reference();
    const auto ref = live.finished();
    if (!ref || !live.key() || frames.interacting()) {
        // The view changed (or is changing): what was measured is of another view.
        if (m_.busy()) m_.cancel();
        const LiveReference::Status st = live.status();
        char b[96];
        std::snprintf(b, sizeof b, "waiting for the reference of this view (%.0f%%)", 100.0 * st.fraction);
        waiting_ = !frames.referenceOn ? "the reference is off (Reference tab): nothing to measure against"
                   : st.state == LiveReference::State::Failed ? "the reference failed: " + st.error
                                                              : std::string(b);
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
    if (m_.busy()) {
        m_.work(budgetMs);
        frames.keepAwake(); // the loop must not sleep while candidates are left
    }
}

size_t FrontPanel::currentIndex() const {
    for (size_t i = 0; i < points().size(); ++i)
        if (points()[i].candidate.current) return i;
    return std::string::npos;
}

size_t FrontPanel::cheapestAtMostCurrentError() const {
    const size_t c = currentIndex();
    if (c == std::string::npos) return c;
    const auto& p = points();
    size_t best = std::string::npos;
    for (size_t i = 0; i < p.size(); ++i)
        if (i != c && p[i].result.error.rmse <= p[c].result.error.rmse &&
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
        if (i != c && p[i].result.gpuMs <= p[c].result.gpuMs &&
            (best == std::string::npos || p[i].result.error.rmse < p[best].result.error.rmse))
            best = i;
    return best;
}

size_t FrontPanel::bestForBudget() const {
    if (!(budgetMs > 0) && !(maxError > 0)) return std::string::npos;
    const auto& p = points();
    size_t best = std::string::npos;
    for (size_t i = 0; i < p.size(); ++i) {
        const ViewResult& r = p[i].result;
        if ((budgetMs > 0 && !(r.gpuMs <= budgetMs)) || (maxError > 0 && !(r.error.rmse <= maxError))) continue;
        if (best == std::string::npos) {
            best = i;
            continue;
        }
        const ViewResult& b = p[best].result;
        // A time budget asks for accuracy; an error bound alone asks for speed (as bench --budget-ms).
        if (budgetMs > 0 ? r.error.rmse < b.error.rmse : r.gpuMs < b.gpuMs) best = i;
    }
    return best;
}

double FrontPanel::referenceNoise() const {
    return points().empty() ? 0.0 : points()[0].result.error.referenceNoise;
}

} // namespace ssao
