#include "view/frame/frame_driver.h"
#include "gl/readback.h"

#include <imgui.h>

#include <algorithm>
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

// What is on screen is all the frame needs: a single AO view culls the composite and the G-buffer
// targets only it reads. The error evaluation (reference on) reads the denoised AO of each chain;
// without it a composite view of reduced AO leaves ao.denoised unwritten and upsamples inline
// (CompositePass::allowFusedUpsample).
// While the cursor (or a pinned pixel) is on the image, the readout lists every buffer at it, so
// every buffer is computed: a culled one printed "-" (reference.ao, composite in a single AO view).
// Passes are config-keyed, so each of those runs once and stays clean while nothing changes.
std::optional<std::set<std::string>> wantedBuffers(const Renderer& r, const ViewState& view, bool error) {
    if (view.mode == ViewMode::Grid || view.cursorOnImage || view.pinPixel) return std::nullopt;
    std::set<std::string> wanted;
    if (error) wanted = {"ao.denoised", "b.ao.denoised"};
    if (view.mode == ViewMode::Single)
        wanted.insert(r.graph().find(view.enlarged) ? view.enlarged : "composite");
    else
        wanted.insert({view.splitBuffer, "b." + view.splitBuffer});
    return wanted;
}
} // namespace

FrameDriver::FrameDriver(const std::string& shaderDir, float renderScale_, float interactiveScale_, bool reference,
                         const std::function<void()>& wake)
    : renderScale(std::clamp(renderScale_, 0.25f, 1.0f)), interactiveScale(std::clamp(interactiveScale_, 0.1f, 1.0f)),
      referenceOn(reference), renderer_(std::make_unique<Renderer>(shaderDir)), reference_(wake) {
    renderer_->enableMotionLods(); // the app moves the camera: skip.motion_lod
    shaderTime_ = renderer_->shaders().newestSourceTime();
}

double FrameDriver::Timing::average(const std::string& pass) const {
    auto it = ms.find(pass);
    if (it == ms.end() || it->second.empty()) return -1.0;
    double s = 0;
    for (double v : it->second)
        s += v;
    return s / double(it->second.size());
}

void FrameDriver::sceneChanged(const Scene& s) {
    renderer_->setScene(s);
    views_.forgetRanges();
    timingFull_ = {};
    timingInteractive_ = {};
    keepAwake();
}

void FrameDriver::noteInteraction() {
    lastInteraction_ = ImGui::GetTime();
    keepAwake();
}

bool FrameDriver::interacting() const {
    return ImGui::GetTime() - lastInteraction_ < kSettleSeconds;
}

void FrameDriver::render(const Input& in, const ViewState& view, int viewW, int viewH) {
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
        // The grid shows the composite in a cell painted at its own size: drawn at that size, the
        // cell the same to the pixel and the pass paying for the cell's pixels, not the frame's
        // (CompositePass::setDisplayWidth).
        r.setDisplayWidth(view.mode == ViewMode::Grid ? view.gridCellPx : 0);
        r.setMoving(inter);       // skip.motion_lod: the clustered mesh while moving
        r.setCamera(in.camera);
        r.setSettings(in.settings);
        r.setSettingsB(in.settingsB);
        r.setReferenceBuffers(reference_.buffers());
        r.setWanted(wantedBuffers(r, view, referenceOn));
        FrameReport rep = r.render(); // cheap when nothing changed: no pass runs
        if (r.accumulating()) keepAwake(); // temporal accumulation: keep drawing until its frames are in
        // The reference after the frame: a trace starts from the view as just rendered (its radius
        // at the centre), and the error needs this frame's ao.denoised. New buffers are uploaded
        // at once (only the upload pass runs), not one frame late.
        if (reference_.update(r, in.scene, referenceOn, std::max(referenceRays, 1), fullSize_.first,
                              fullSize_.second, inter, [this] { return radiusInfo().world; })) {
            r.setReferenceBuffers(reference_.buffers());
            rep = merged(rep, r.render());
        }
        recordTimings(rep, inter, w, h);
        renderedInteractive_ = inter;
        if (inter) keepAwake(2); // keep drawing until the full-resolution frame after input stops
        paintViews(view);
        if (views_.fitsPending()) keepAwake(1); // the fits deferred from this frame (buffer_views.h)
    } catch (const std::exception& e) {
        // A shader that fails mid-session (e.g. a new variant after hot reload) must not kill the app.
        shaderError_ = e.what();
    }
}

void FrameDriver::recordTimings(const FrameReport& rep, bool interactive, int w, int h) {
    if (rep.ran().empty()) return;
    lastReport_ = rep;
    ++framesRendered_;
    Timing& t = interactive ? timingInteractive_ : timingFull_;
    if (t.width != w || t.height != h) t = Timing{w, h, {}}; // never average across sizes
    for (const auto& p : rep.passes) {
        if (!p.ran || p.gpuMs < 0) continue;
        auto& q = t.ms[p.name];
        q.push_back(p.gpuMs);
        if (q.size() > kTimingHistory) q.pop_front();
    }
}

// Paints only what is on screen.
void FrameDriver::paintViews(const ViewState& view) {
    Renderer& r = *renderer_;
    std::vector<std::string> names;
    if (view.mode == ViewMode::Grid) {
        for (const Resource* res : r.buffers())
            names.push_back(res->desc.name);
    } else if (view.mode == ViewMode::Single) {
        names.push_back(r.graph().find(view.enlarged) ? view.enlarged : "composite");
    } else if (!view.splitDifference) {
        names = {view.splitBuffer, "b." + view.splitBuffer};
    }
    // Grid cells are painted at their own size (a paint costs its output's pixels, and a cell has
    // far fewer than its buffer); an enlarged view at the buffer's.
    // While moving, fitted ranges stay those of the last still frame (no read-back per frame).
    views_.update(r, view.style, names, view.mode == ViewMode::Grid ? view.gridCellPx : 0, renderedInteractive_);
    if (view.mode == ViewMode::Split && view.splitDifference && r.graph().find("b." + view.splitBuffer))
        views_.difference(r, view.splitBuffer, "b." + view.splitBuffer, view.diffScale);
}

const RadiusInfo& FrameDriver::radiusInfo() {
    // Keyed by what the radius depends on, so a UI frame neither reads the GPU back nor serialises
    // the settings when nothing changed.
    const Resource* depth = renderer_->graph().find("gbuffer.depth");
    const AoSettings& a = renderer_->settings().ao;
    char key[200];
    std::snprintf(key, sizeof key, "%llu/%u/%dx%d/%d/%a/%a/%a", depth ? (unsigned long long)depth->version : 0ull,
                  depth ? depth->generation : 0u, renderer_->width(), renderer_->height(), int(a.radiusMode),
                  a.radius, a.radiusScene, a.radiusPx);
    if (radiusKey_ != key) {
        radius_ = renderer_->radiusAtCentre();
        radiusKey_ = key;
    }
    return radius_;
}

const ViewRadiusCheck& FrameDriver::viewRadius() {
    const Resource* depth = renderer_->graph().find("gbuffer.depth");
    if (!depth || renderedInteractive_ || interacting()) return viewRadius_;
    const AoSettings& a = renderer_->settings().ao;
    char key[160];
    std::snprintf(key, sizeof key, "%llu/%u/%d/%a", (unsigned long long)depth->version, depth->generation,
                  int(a.radiusMode), a.radiusScene);
    if (viewRadiusKey_ != key) {
        const Image d = readBack(depth->texture, 1);
        viewRadius_ = checkViewRadius(d.data.data(), d.data.size(), renderer_->camera(),
                                      double(std::max(d.width, 1)) / double(std::max(d.height, 1)), a,
                                      2.0 * double(renderer_->sceneRadius()));
        viewRadiusKey_ = key;
    }
    return viewRadius_;
}

void FrameDriver::noteFrameMs(float ms) {
    frameMs_.push_back(ms);
    if (frameMs_.size() > 120) frameMs_.pop_front();
}

void FrameDriver::pollShaderReload() {
    const auto t = renderer_->shaders().newestSourceTime();
    if (t == shaderTime_) return;
    shaderTime_ = t;
    try {
        renderer_->shaders().reload();
        renderer_->invalidate();
        shaderError_.clear();
        reloaded_ = true;
    } catch (const std::exception& e) {
        shaderError_ = e.what(); // the last good programs keep running
    }
    keepAwake();
}

} // namespace ssao
