#include "renderer.h"

#include "gl/shader_library.h"
#include "output/image.h"
#include "passes/composite_pass.h"
#include "passes/denoise_pass.h"
#include "passes/gbuffer_pass.h"
#include "scene/view_fit.h"
#include "settings/params.h"
#include "techniques/ao_common.h"
#include "techniques/technique.h"
#include "util/error.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <typeinfo>

namespace ssao {

void checkRenderSize(int width, int height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) throw Error("size " + size + ": width and height must be positive");
    if (width > kMaxRenderSide || height > kMaxRenderSide || long(width) * long(height) > kMaxRenderPixels)
        throw Error("size " + size + " is too large: at most " + std::to_string(kMaxRenderSide) +
                    " a side and " + std::to_string(kMaxRenderPixels / 1000000) +
                    " million pixels (e.g. 4096x4096)");
}

gpu::FrameConstants packFrameConstants(const Camera& cam, int width, int height, float sceneRadius,
                                       int frameIndex) {
    gpu::FrameConstants f{};
    f.view = cam.view();
    f.proj = cam.projection(float(width) / float(height));
    f.invProj = glm::inverse(f.proj);
    f.viewport = {float(width), float(height), 1.0f / float(width), 1.0f / float(height)};
    f.clip = {cam.nearZ, cam.farZ, sceneRadius, float(frameIndex)};
    f.camera = {cam.orthographic() ? 1.0f : 0.0f, cam.depth == DepthMode::Reversed ? 1.0f : 0.0f, 0.0f, 0.0f};
    return f;
}

Renderer::Renderer(const std::string& shaderDir)
    : shaders_(shaderDir), frameUbo_(sizeof(gpu::FrameConstants), "frame.constants") {
    // llvmpipe answers the first GL_TIME_ELAPSED query around a context's first drawing with
    // the time since boot (seen: 2.4e6 ms). One tiny clear inside a query up front keeps every
    // reported pass time real.
    gl::RenderTarget scratch;
    scratch.ensure(1, 1, GL_R8, "timer-warm-up");
    gl::GpuTimer warmUp;
    warmUp.begin();
    scratch.bind();
    glClear(GL_COLOR_BUFFER_BIT);
    warmUp.end();
    warmUp.resultMs();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene) {
    scene_ = std::make_unique<GpuScene>(scene);
    bounds_ = scene.bounds;
    ++sceneVersion_;
    frame_.scene = nullptr; // until the next render(): the inspector must not draw the old scene
}

void Renderer::setCamera(const Camera& camera) {
    validateCamera(camera);
    camera_ = camera;
}

void Renderer::setSettings(const Settings& settings) {
    findTechnique(settings.ao.technique); // an unknown id fails here, naming the known ones
    if (settings == settings_) return;
    settings_ = settings;
    graphStale_ = true;
}

void Renderer::setSettingsB(std::optional<Settings> settings) {
    if (settings) findTechnique(settings->ao.technique);
    if (settings.has_value() == settingsB_.has_value() && (!settings || *settings == *settingsB_)) return;
    settingsB_ = std::move(settings);
    graphStale_ = true;
}

void Renderer::setSize(int width, int height) {
    checkRenderSize(width, height);
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    graphStale_ = true;
}

void Renderer::setDisplayScale(float scale) {
    if (!(scale > 0.0f) || !std::isfinite(scale)) throw Error("display scale must be positive");
    displayScale_ = scale;
}

void Renderer::setReferenceBuffers(std::shared_ptr<const ReferenceBuffers> buffers) {
    if (bool(buffers) != referenceOn_) graphStale_ = true; // the two buffers join or leave the graph
    referenceOn_ = bool(buffers);
    referencePass_.setBuffers(std::move(buffers));
}

Pass& Renderer::passFor(const std::string& key, const std::function<std::unique_ptr<Pass>()>& make) {
    auto& slot = passes_[key];
    if (!slot) slot = make();
    return *slot;
}

std::vector<Pass*> Renderer::techniquePasses(const Branch& b, const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    auto& owned = techniquePasses_[b.prefix + t.id];
    if (owned.empty()) owned = t.makePasses(b);
    std::vector<Pass*> out;
    for (auto& p : owned)
        out.push_back(p.get());
    return out;
}

void Renderer::buildGraph() {
    std::vector<FrameGraph::Node> nodes;
    std::map<std::string, std::string> aliases;
    nodes.push_back({&passFor("gbuffer", [] { return std::make_unique<GBufferPass>(); }), &settings_});
    auto chain = [&](const Branch& b, const Settings& s) {
        std::vector<Pass*> passes = techniquePasses(b, s);
        passes.push_back(&passFor(b.prefix + "denoise", [&] { return std::make_unique<DenoisePass>(b); }));
        passes.push_back(
            &passFor(b.prefix + "composite", [&] { return std::make_unique<CompositePass>(b); }));
        return passes;
    };
    const std::vector<Pass*> a = chain(Branch::a(), settings_);
    for (Pass* p : a)
        nodes.push_back({p, &settings_});
    if (referenceOn_) nodes.push_back({&referencePass_, &settings_}); // chain A's; reads nothing
    if (settingsB_) {
        // A pass of chain B whose settings groups and (resolved) inputs equal its chain-A
        // counterpart's would compute the same image: its outputs alias A's instead of running.
        const nlohmann::json ja = toEffectiveJson(settings_), jb = toEffectiveJson(*settingsB_);
        const std::vector<Pass*> b = chain(Branch::b(), *settingsB_);
        const bool sameShape = a.size() == b.size(); // another technique may have another number of passes
        for (size_t i = 0; i < b.size(); ++i) {
            bool same = sameShape && typeid(*a[i]) == typeid(*b[i]);
            PassDecl da, db;
            if (same)
                da = FrameGraph::declare(*a[i], settings_), db = FrameGraph::declare(*b[i], *settingsB_);
            same = same && da.groups == db.groups && da.reads.size() == db.reads.size() &&
                   da.writes.size() == db.writes.size();
            for (size_t g = 0; same && g < db.groups.size(); ++g)
                same = FrameGraph::keyedSettings(ja, db.groups[g]) == FrameGraph::keyedSettings(jb, db.groups[g]);
            for (size_t r = 0; same && r < db.reads.size(); ++r) {
                auto it = aliases.find(db.reads[r]);
                same = (it != aliases.end() ? it->second : db.reads[r]) == da.reads[r];
            }
            if (same) {
                for (size_t w = 0; w < db.writes.size(); ++w)
                    aliases[db.writes[w].name] = da.writes[w].name;
            } else {
                nodes.push_back({b[i], &*settingsB_});
            }
        }
    }
    graph_.compile(nodes, aliases, width_, height_);
    graphStale_ = false;
}

FrameReport Renderer::render() {
    if (!scene_) throw Error("renderer: no scene set");
    if (width_ <= 0) throw Error("renderer: no size set");
    effective_ = effectiveCamera(camera_, bounds_);
    // Temporal accumulation: a settings/size/scene change drops the history, a camera change only
    // restarts the count (the history is reprojected); while counting, every pass re-runs with a
    // new frame index (new noise).
    int frameIndex = 0;
    bool reset = true;
    if (settings_.temporal.enabled) {
        const Camera& c = effective_;
        const Camera& p = temporalCamera_;
        const bool sameCamera = c == p;
        reset = !temporalSettings_ || *temporalSettings_ != settings_ ||
                temporalSize_ != glm::ivec2(width_, height_) || temporalScene_ != sceneVersion_;
        if (reset || !sameCamera) temporalFrame_ = 0;
        temporalSettings_ = settings_;
        temporalCamera_ = c;
        temporalSize_ = {width_, height_};
        temporalScene_ = sceneVersion_;
        if (temporalFrame_ < settings_.temporal.frames) {
            graph_.invalidate();
            frameIndex = temporalFrame_++;
        } else {
            frameIndex = temporalFrame_ - 1;
        }
    } else {
        temporalFrame_ = 0;
        temporalSettings_.reset();
    }
    const gpu::FrameConstants fc = packFrameConstants(effective_, width_, height_, sceneRadius(), frameIndex);
    frameUbo_.upload(&fc, sizeof fc);
    frameUbo_.bind(SSAO_UBO_FRAME);
    if (graphStale_) buildGraph(); // only when settings, chain B, the size or the reference changed
    frame_ = FrameInfo{scene_.get(), sceneVersion_, sceneRadius(), &effective_, width_,
                       height_,      displayScale_, frameIndex,    reset};
    return graph_.execute(frame_, shaders_, triangle_);
}

bool Renderer::accumulating() const {
    return settings_.temporal.enabled && temporalFrame_ < settings_.temporal.frames;
}

std::vector<const Resource*> Renderer::buffers() const {
    std::vector<const Resource*> out;
    for (const Resource* r : graph_.resources())
        if (r->desc.name.rfind(Branch::b().prefix, 0) != 0) out.push_back(r);
    return out;
}

std::optional<PixelInspection> Renderer::inspect(int branch, glm::ivec2 pixel) {
    const Branch b = branch == 1 ? Branch::b() : Branch::a();
    // Chain B's AO may be an alias of A's: inspect the pass that really produced it.
    const Resource* ao = graph_.find(b.res("ao.raw"));
    if (!ao || !frame_.scene || graphStale_) return std::nullopt; // render() first
    Pass* p = graph_.pass(ao->producer);
    const Settings* s = graph_.settingsOf(ao->producer);
    if (!p || !s || pixel.x < 0 || pixel.y < 0 || pixel.x >= width_ || pixel.y >= height_)
        return std::nullopt;
    const glm::ivec2 aoPixel(mapPixel(pixel.x, width_, ao->width()),
                             mapPixel(pixel.y, height_, ao->height()));
    frameUbo_.bind(SSAO_UBO_FRAME);
    PassContext ctx(graph_, *s, frame_, shaders_, triangle_, ao->producer);
    PixelInspection out;
    if (!p->inspect(ctx, aoPixel, out)) return std::nullopt;
    return out;
}

void Renderer::setWanted(std::optional<std::set<std::string>> buffers) {
    if (buffers) buffers->insert("gbuffer.depth");
    graph_.setWanted(std::move(buffers));
}

RadiusInfo Renderer::radiusAtCentre() const {
    RadiusInfo ri;
    ri.sceneDiagonal = 2.0f * sceneRadius();
    const Camera& c = effective_;
    if (const Resource* d = graph_.find("gbuffer.depth"))
        ri.depth = d->texture.readTexel(d->width() / 2, d->height() / 2).x;
    if (!(ri.depth > 0.0f)) ri.depth = glm::length(camera_.target - camera_.eye); // sky at the centre
    const int h = height_ > 0 ? height_ : 1;
    // Displayed pixels: a render at 0.35 of the view has pixels 1/0.35 times as large.
    const float upp =
        unitsPerPixelAtUnitDepth(c.projection(float(std::max(width_, 1)) / float(h)), h) * displayScale_;
    const float depthScale = c.orthographic() ? 1.0f : ri.depth; // pixels do not shrink with depth
    ri.world = worldRadius(settings_.ao, ri.sceneDiagonal, depthScale, upp);
    ri.pixels = radiusInPixels(settings_.ao, ri.sceneDiagonal, depthScale, upp);
    return ri;
}

} // namespace ssao
