#include "renderer.h"

#include "base/image.h"
#include "gl/shader_library.h"
#include "passes/back_face_pass.h"
#include "passes/composite_pass.h"
#include "passes/denoise_pass.h"
#include "passes/gbuffer_pass.h"
#include "passes/guard_band_pass.h"
#include "passes/position_pyramid_pass.h"
#include "passes/second_layer_pass.h"
#include "scene/view_fit.h"
#include "settings/params.h"
#include "techniques/ao_common.h"
#include "techniques/technique.h"
#include "util/error.h"

#include <glm/gtc/matrix_inverse.hpp>

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
    // the time since boot. One tiny clear inside a query up front keeps every
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
    scene_ = std::make_unique<GpuScene>(scene, motionLods_);
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
    validateSettings(settings);           // every range, once: the packing functions trust it
    if (settings == settings_) return;
    settings_ = settings;
    graphStale_ = true;
}

void Renderer::setSettingsB(std::optional<Settings> settings) {
    if (settings) findTechnique(settings->ao.technique), validateSettings(*settings);
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

void Renderer::setDisplayWidth(int px) {
    if (px < 0) throw Error("display width must be 0 or positive");
    if (px == displayWidth_) return;
    displayWidth_ = px;
    graphStale_ = true; // the composite's size
}

void Renderer::setFrameTimeLimit(double seconds) {
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) throw Error("frame time limit must be 0 (none) or positive");
    if (watchdog_ && watchdog_->seconds() == seconds) return;
    watchdog_ = seconds > 0.0 ? std::make_unique<gl::FrameWatchdog>(seconds) : nullptr;
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

std::vector<Pass*> Renderer::techniquePasses(const Chain& b, const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    // A user technique's new version (its file's hash) gets new passes; the old version's go.
    const std::string key = b.prefix + t.id, versioned = key + "#" + t.version;
    for (auto it = techniquePasses_.lower_bound(key + "#"); it != techniquePasses_.end() && it->first.rfind(key + "#", 0) == 0;)
        it = it->first != versioned ? techniquePasses_.erase(it) : std::next(it);
    auto& owned = techniquePasses_[versioned];
    if (owned.empty()) owned = t.makePasses(b);
    std::vector<Pass*> out;
    for (auto& p : owned)
        out.push_back(p.get());
    return out;
}

std::vector<Pass*> Renderer::chainPasses(const Chain& c, const Settings& s) {
    std::vector<Pass*> passes = techniquePasses(c, s);
    passes.push_back(&passFor(c.prefix + "denoise", [&] { return std::make_unique<DenoisePass>(c); }));
    Pass& composite = passFor(c.prefix + "composite", [&] { return std::make_unique<CompositePass>(c); });
    static_cast<CompositePass&>(composite).allowFusedUpsample(c.prefix.empty() ? fuseA_ : fuseB_);
    static_cast<CompositePass&>(composite).setDisplayWidth(displayWidth_);
    passes.push_back(&composite);
    return passes;
}

std::vector<bool> Renderer::sharedWithChainA(std::map<std::string, std::string>* aliases) {
    // A pass of chain B whose type, config and (resolved) inputs equal its chain-A counterpart's
    // computes the same image: its outputs alias A's instead of running. Configs are compared for
    // this frame; render() compares again every frame, so a later frame that tells them apart (a
    // radius in scene units against one in world units, on another scene) rebuilds the graph.
    const std::vector<Pass*> a = chainPasses(Chain::a(), settings_), b = chainPasses(Chain::b(), *settingsB_);
    std::map<std::string, std::string> local;
    std::map<std::string, std::string>& alias = aliases ? *aliases : local;
    std::vector<bool> shared(b.size(), false);
    const bool sameShape = a.size() == b.size(); // another technique may have another number of passes
    for (size_t i = 0; i < b.size() && sameShape; ++i) {
        if (typeid(*a[i]) != typeid(*b[i])) continue;
        const PassDecl da = FrameGraph::declare(*a[i], settings_), db = FrameGraph::declare(*b[i], *settingsB_);
        bool same = da.reads.size() == db.reads.size() && da.writes.size() == db.writes.size() &&
                    a[i]->configure(settings_, frame_) == b[i]->configure(*settingsB_, frame_);
        for (size_t r = 0; same && r < db.reads.size(); ++r) {
            auto it = alias.find(db.reads[r]);
            same = (it != alias.end() ? it->second : db.reads[r]) == da.reads[r];
        }
        for (size_t w = 0; same && w < db.writes.size(); ++w)
            same = db.writes[w].format == da.writes[w].format && db.writes[w].scale == da.writes[w].scale;
        if (!same) continue;
        shared[i] = true;
        for (size_t w = 0; w < db.writes.size(); ++w)
            alias[db.writes[w].name] = da.writes[w].name;
    }
    return shared;
}

void Renderer::buildGraph() {
    std::vector<FrameGraph::Node> nodes;
    std::map<std::string, std::string> aliases;
    gbufferSettings_ = settings_;
    if (!settings_.gbuffer.secondLayer && settingsB_ && settingsB_->gbuffer.secondLayer) {
        gbufferSettings_.gbuffer.secondLayer = true;
        gbufferSettings_.gbuffer.secondLayerSeparation = settingsB_->gbuffer.secondLayerSeparation;
        gbufferSettings_.gbuffer.secondLayerBuild = settingsB_->gbuffer.secondLayerBuild;
    }
    nodes.push_back({&passFor("gbuffer", [] { return std::make_unique<GBufferPass>(); }), &gbufferSettings_});
    // The guard band, shared by both chains, as wide as the wider chain asks.
    const int band = std::max(GuardBandPass::bandOf(settings_), settingsB_ ? GuardBandPass::bandOf(*settingsB_) : 0);
    if (band > 0)
        nodes.push_back({&passFor("guard_band:" + std::to_string(band),
                                  [band] { return std::make_unique<GuardBandPass>(band); }),
                         &settings_});
    // The back-face layer, shared likewise.
    if (BackFacePass::on(settings_) || (settingsB_ && BackFacePass::on(*settingsB_)))
        nodes.push_back({&passFor("back_faces", [] { return std::make_unique<BackFacePass>(); }), &settings_});
    if (SecondLayerPass::on(gbufferSettings_))
        nodes.push_back({&passFor("second_layer", [] { return std::make_unique<SecondLayerPass>(); }), &gbufferSettings_});
    // The position pyramid, shared by both chains, when a chain's technique reads it.
    if (usesPyramid(settings_) || (settingsB_ && usesPyramid(*settingsB_)))
        nodes.push_back({&passFor("position_mips", [] { return std::make_unique<PositionPyramidPass>(); }),
                         &settings_}); // the G-buffer's formats are chain A's
    for (Pass* p : chainPasses(Chain::a(), settings_))
        nodes.push_back({p, &settings_});
    if (referenceOn_) nodes.push_back({&referencePass_, &settings_}); // chain A's; reads nothing
    sharedB_.clear();
    if (settingsB_) {
        sharedB_ = sharedWithChainA(&aliases);
        const std::vector<Pass*> b = chainPasses(Chain::b(), *settingsB_);
        for (size_t i = 0; i < b.size(); ++i)
            if (!sharedB_[i]) nodes.push_back({b[i], &*settingsB_});
    }
    graph_.compile(nodes, aliases, width_, height_);
    graphStale_ = false;
    techniquesGeneration_ = techniquesGeneration();
}

FrameReport Renderer::render() {
    if (!scene_) throw Error("renderer: no scene set");
    if (width_ <= 0) throw Error("renderer: no size set");
    // Watched from here (the passes' compiles count too) until the frame's GL work is done.
    const TechniqueInfo& technique = findTechnique(settings_.ao.technique);
    gl::FrameWatchdog::Frame watch(watchdog_.get(), technique.file.empty() ? "technique " + technique.id : technique.file);
    effective_ = effectiveCamera(camera_, bounds_);
    // Temporal accumulation: a settings/size/scene change drops the history, a camera change only
    // restarts the count (the history is reprojected); while counting, the frame index advances and
    // every pass whose config holds it (AO noise, the accumulation) re-runs.
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
        frameIndex = temporalFrame_ < settings_.temporal.frames ? temporalFrame_++ : temporalFrame_ - 1;
    } else {
        temporalFrame_ = 0;
        temporalSettings_.reset();
    }
    frame_ = FrameInfo{scene_.get(), sceneVersion_, sceneRadius(), &effective_, width_,
                       height_,      displayScale_, frameIndex,    reset};
    frame_.lod = -1; // the coarsest level whose cell covers at most a pixel here (motion_lod.h)
    for (int l = 0; moving_ && settings_.skip.motionLod && l < scene_->lodLevels() && frame_.lod < 0; ++l)
        if (scene_->lodCellPx(l, effective_, height_) <= 1.0f) frame_.lod = l;
    frame_.constants = packFrameConstants(effective_, width_, height_, sceneRadius(), frameIndex);
    frameUbo_.upload(&frame_.constants, sizeof frame_.constants);
    frameUbo_.bind(SSAO_UBO_FRAME);
    // Only when settings, chain B, the size or the reference changed - or this frame tells apart
    // chain-B passes that were shared (or shares ones that were not).
    if (techniquesGeneration_ != techniquesGeneration()) graphStale_ = true; // a user technique changed
    if (graphStale_ || (settingsB_ && sharedWithChainA(nullptr) != sharedB_)) buildGraph();
    return graph_.execute(frame_, shaders_, triangle_, [&watch] { watch.waitForGpu(); });
}

bool Renderer::accumulating() const {
    return settings_.temporal.enabled && temporalFrame_ < settings_.temporal.frames;
}

std::vector<const Resource*> Renderer::buffers() const {
    std::vector<const Resource*> out;
    for (const Resource* r : graph_.resources())
        if (r->desc.name.rfind(Chain::b().prefix, 0) != 0) out.push_back(r);
    return out;
}

std::optional<PixelInspection> Renderer::inspect(int chain, glm::ivec2 pixel) {
    const Chain b = chain == 1 ? Chain::b() : Chain::a();
    // Chain B's AO may be an alias of A's: inspect the pass that really produced it.
    const Resource* ao = graph_.find(b.res("ao.raw"));
    if (!ao || !frame_.scene || graphStale_) return std::nullopt; // render() first
    Pass* p = graph_.pass(ao->producer);
    const ConfigKey* config = graph_.lastConfig(ao->producer); // what its last run drew with
    if (!p || !config || pixel.x < 0 || pixel.y < 0 || pixel.x >= width_ || pixel.y >= height_)
        return std::nullopt;
    const glm::ivec2 aoPixel(mapPixel(pixel.x, width_, ao->width()),
                             mapPixel(pixel.y, height_, ao->height()));
    frameUbo_.bind(SSAO_UBO_FRAME);
    PassContext ctx(graph_, *config, frame_.scene, shaders_, triangle_, ao->producer);
    PixelInspection out;
    if (!p->inspect(ctx, aoPixel, out)) return std::nullopt;
    return out;
}

void Renderer::setWanted(std::optional<std::set<std::string>> buffers) {
    if (buffers) buffers->insert("gbuffer.depth");
    const bool fuseA = buffers && !buffers->count(Chain::a().res("ao.denoised"));
    const bool fuseB = buffers && !buffers->count(Chain::b().res("ao.denoised"));
    // The composite's inputs change only where its chain has skip.fused_upsample on: otherwise the
    // cursor crossing the image (the readout then wants every buffer) rebuilds nothing.
    if ((fuseA != fuseA_ && settings_.skip.fusedUpsample) ||
        (fuseB != fuseB_ && settingsB_ && settingsB_->skip.fusedUpsample))
        graphStale_ = true;
    fuseA_ = fuseA;
    fuseB_ = fuseB;
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
