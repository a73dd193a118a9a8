// AppCore's per-frame work: rendering at the interactive or full scale, views, the inspector,
// timings, shader hot reload.
#include "view/app_core.h"

#include <cmath>

namespace ssao {

namespace {
constexpr size_t kTimingHistory = 60;
constexpr double kSettleSeconds = 0.25; // input quiet this long: refine to full resolution
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

void AppCore::renderIfNeeded(int viewW, int viewH) {
    const bool inter = interacting();
    const float scale = inter ? std::min(interactiveScale, renderScale) : renderScale;
    const int w = std::max(int(std::lround(float(viewW) * scale)), 16);
    const int h = std::max(int(std::lround(float(viewH) * scale)), 16);
    try {
        Renderer& r = *renderer_;
        if (r.width() != w || r.height() != h) r.setSize(w, h);
        r.setCamera(camera_.camera());
        r.setSettings(settings_);
        r.setSettingsB(settingsB());
        FrameReport rep = r.render(); // cheap when nothing changed: no pass runs
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
    if (hoverPixel != inspectedPixel_ || hoverBranch != inspectedBranch_ || v != inspectedVersion_) {
        try {
            inspection_ = renderer_->inspect(hoverBranch, hoverPixel);
        } catch (const std::exception& e) {
            inspection_.reset();
            shaderError_ = e.what();
        }
        inspectedPixel_ = hoverPixel;
        inspectedBranch_ = hoverBranch;
        inspectedVersion_ = v;
    }
    return inspection_;
}

std::vector<float> AppCore::valueAt(const std::string& buffer, glm::ivec2 pixel) {
    const Resource* res = renderer_->graph().find(buffer);
    if (!res || pixel.x < 0 || pixel.y < 0) return {};
    const Renderer& r = *renderer_;
    const int x = std::min(res->width() - 1, pixel.x * res->width() / std::max(r.width(), 1));
    const int y = std::min(res->height() - 1, pixel.y * res->height() / std::max(r.height(), 1));
    const glm::vec4 t = res->texture.readTexel(x, y);
    std::vector<float> out;
    for (int c = 0; c < std::max(1, res->desc.channels); ++c)
        out.push_back(res->desc.display == Display::Color
                          ? t[c]
                          : t[c] * res->desc.decodeScale + res->desc.decodeOffset);
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
