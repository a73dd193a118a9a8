// AppCore's per-frame work: rendering at the interactive or full scale, views, the inspector,
// timings, shader hot reload.
#include "view/app_core.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace ssao {

namespace {
constexpr size_t kTimingHistory = 60;
constexpr double kSettleSeconds = 0.25; // input quiet this long: refine to full resolution

// `first` and then `second` rendered in one UI frame: what ran in either, in `second`'s order (its
// graph may have gained or lost the reference's pass).
FrameReport merged(const FrameReport& first, const FrameReport& second) {
    FrameReport out = second;
    for (PassReport& p : out.passes) {
        if (p.ran) continue;
        for (const PassReport& q : first.passes)
            if (q.name == p.name && q.ran) p = q;
    }
    return out;
}

} // namespace

double AppCore::Timing::average(const std::string& pass) const {
    auto it = ms.find(pass);
    if (it == ms.end() || it->second.empty()) return -1.0;
    double s = 0;
    for (double v : it->second)
        s += v;
    return s / double(it->second.size());
}

void AppCore::noteInteraction() {
    lastInteraction_ = ImGui::GetTime();
    poke();
}

bool AppCore::interacting() const {
    return ImGui::GetTime() - lastInteraction_ < kSettleSeconds;
}

glm::ivec2 AppCore::hoverPixel() const {
    const Renderer& r = *renderer_;
    if (hoverUv.x < 0.0f || r.width() <= 0) return {-1, -1};
    return {std::clamp(int(hoverUv.x * float(r.width())), 0, r.width() - 1),
            std::clamp(int(hoverUv.y * float(r.height())), 0, r.height() - 1)};
}

void AppCore::renderIfNeeded(int viewW, int viewH) {
    const bool inter = interacting();
    const float scale = inter ? std::min(interactiveScale, renderScale) : renderScale;
    const int w = std::max(int(std::lround(float(viewW) * scale)), 16);
    const int h = std::max(int(std::lround(float(viewH) * scale)), 16);
    fullSize_ = {std::max(int(std::lround(float(viewW) * renderScale)), 16),
                 std::max(int(std::lround(float(viewH) * renderScale)), 16)};
    try {
        Renderer& r = *renderer_;
        if (r.width() != w || r.height() != h) r.setSize(w, h);
        r.setDisplayScale(scale); // a radius in pixels stays in displayed pixels while moving
        r.setCamera(camera_.camera());
        r.setSettings(settings_);
        r.setSettingsB(settingsB());
        r.setReferenceBuffers(reference_.buffers());
        // What is on screen is all the frame needs: a single AO view culls the composite and the
        // G-buffer targets only it reads. The error evaluation reads the denoised AO of each chain.
        if (viewMode == ViewMode::Grid) {
            r.setWanted(std::nullopt);
        } else {
            std::set<std::string> wanted = {"ao.denoised", "b.ao.denoised"};
            if (viewMode == ViewMode::Single)
                wanted.insert(r.graph().find(enlarged) ? enlarged : "composite");
            else
                wanted.insert({splitBuffer, "b." + splitBuffer});
            r.setWanted(wanted);
        }
        FrameReport rep = r.render(); // cheap when nothing changed: no pass runs
        if (r.accumulating()) poke(); // temporal accumulation: keep drawing until its frames are in
        // The reference after the frame: a trace starts from the view as just rendered (its radius
        // at the centre), and the error needs this frame's ao.denoised. New buffers are uploaded
        // at once (only the upload pass runs), not one frame late.
        if (reference_.update(r, scene_, referenceOn, std::max(referenceRays, 1), fullSize_.first,
                              fullSize_.second, inter, [this] { return radiusInfo().world; })) {
            r.setReferenceBuffers(reference_.buffers());
            rep = merged(rep, r.render());
        }
        if (!rep.ran().empty()) {
            lastReport_ = rep;
            ++framesRendered_;
            Timing& t = inter ? timingInteractive_ : timingFull_;
            if (t.width != w || t.height != h) t = Timing{w, h, {}}; // never average across sizes
            for (const auto& p : rep.passes) {
                if (!p.ran || p.gpuMs < 0) continue;
                auto& q = t.ms[p.name];
                q.push_back(p.gpuMs);
                if (q.size() > kTimingHistory) q.pop_front();
            }
        }
        renderedInteractive_ = inter;
        if (inter) poke(2); // keep drawing until the full-resolution frame after input stops

        // Paint only what is on screen.
        std::vector<std::string> names;
        if (viewMode == ViewMode::Grid) {
            for (const Resource* res : r.buffers())
                names.push_back(res->desc.name);
        } else if (viewMode == ViewMode::Single) {
            names.push_back(r.graph().find(enlarged) ? enlarged : "composite");
        } else if (!splitDifference) {
            names = {splitBuffer, "b." + splitBuffer};
        }
        views_.update(r, style, names);
        if (viewMode == ViewMode::Split && splitDifference && r.graph().find("b." + splitBuffer))
            views_.difference(r, splitBuffer, "b." + splitBuffer, diffScale);
    } catch (const std::exception& e) {
        // A shader that fails mid-session (e.g. a new variant after hot reload) must not kill the app.
        shaderError_ = e.what();
    }
}

const std::optional<PixelInspection>& AppCore::inspection() {
    const Resource* ao = renderer_->graph().find(hoverBranch ? "b.ao.raw" : "ao.raw");
    const uint64_t v = ao ? ao->version : 0;
    const glm::ivec2 px = hoverPixel();
    // While the view moves the AO changes every frame: keep the last record instead of running the
    // probe (a full-shader draw and a read-back) each time.
    const bool moved = px != inspectedPixel_ || hoverBranch != inspectedBranch_;
    if (moved || (v != inspectedVersion_ && !interacting())) {
        try {
            inspection_ = renderer_->inspect(hoverBranch, px);
        } catch (const std::exception& e) {
            inspection_.reset();
            shaderError_ = e.what();
        }
        inspectedPixel_ = px;
        inspectedBranch_ = hoverBranch;
        inspectedVersion_ = v;
    }
    return inspection_;
}

const RadiusInfo& AppCore::radiusInfo() {
    // Keyed by what the radius depends on, so a UI frame neither reads the GPU back nor serialises
    // the settings when nothing changed.
    const Resource* depth = renderer_->graph().find("gbuffer.depth");
    const AoSettings& a = renderer_->settings().ao;
    char key[200];
    std::snprintf(key, sizeof key, "%llu/%u/%dx%d/%d/%a/%a/%a",
                  depth ? (unsigned long long)depth->version : 0ull, depth ? depth->generation : 0u,
                  renderer_->width(), renderer_->height(), int(a.radiusMode), a.radius, a.radiusScene,
                  a.radiusPx);
    if (radiusKey_ != key) {
        radius_ = renderer_->radiusAtCentre();
        radiusKey_ = key;
    }
    return radius_;
}

std::vector<float> AppCore::valueAt(const std::string& buffer, glm::ivec2 pixel) {
    const Resource* res = renderer_->graph().find(buffer);
    // A buffer the current view does not need was not computed this frame: show nothing, not stale data.
    if (!res || pixel.x < 0 || pixel.y < 0 || !renderer_->graph().current(buffer)) return {};
    CachedValue& c = values_[buffer];
    if (c.pixel == pixel && c.version == res->version && c.generation == res->generation) return c.values;
    const Renderer& r = *renderer_;
    const int x = mapPixel(pixel.x, std::max(r.width(), 1), res->width());
    const int y = mapPixel(pixel.y, std::max(r.height(), 1), res->height());
    const glm::vec4 t = res->texture.readTexel(x, y);
    std::vector<float> out;
    for (int ch = 0; ch < std::max(1, res->desc.channels); ++ch)
        out.push_back(res->desc.display == Display::Color
                          ? t[ch]
                          : t[ch] * res->desc.decodeScale + res->desc.decodeOffset);
    c = {pixel, res->version, res->generation, out};
    return out;
}

void AppCore::noteFrameMs(float ms) {
    frameMs_.push_back(ms);
    if (frameMs_.size() > 120) frameMs_.pop_front();
}

void AppCore::pollShaderReload() {
    const auto t = renderer_->shaders().newestSourceTime();
    if (t == shaderTime_) return;
    shaderTime_ = t;
    try {
        renderer_->shaders().reload();
        renderer_->invalidate();
        shaderError_.clear();
        setStatus("shaders reloaded", false);
    } catch (const std::exception& e) {
        shaderError_ = e.what(); // the last good programs keep running
        poke();
    }
}

} // namespace ssao
