// A pass is a small class with declared inputs and outputs. setup() declares, for the current
// settings, which resources it reads and writes; configure() derives its config from the settings
// and the frame (graph/pass_config.h). The frame graph orders passes from the declarations and
// re-runs a pass only when its config or its inputs changed (filament's frame graph, reduced).
#pragma once
#include "graph/inspection.h"
#include "graph/pass_config.h"
#include "graph/resource.h"

#include "../../shaders/include/bindings.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ssao {

namespace gl {
class ShaderLibrary;
class FullscreenTriangle;
} // namespace gl
class GpuScene;
class FrameGraph;
struct Camera;
struct Settings; // techniques/technique_settings.h: the graph passes it through, a pass reads it

// Which AO chain a pass belongs to: A (the main one, unprefixed names) or B (the split view's
// second chain, names prefixed "b."). Both share the G-buffer.
struct Chain {
    int index = 0;
    std::string prefix; // "" or "b."
    std::string res(const std::string& name) const { return prefix + name; }
    static Chain a() { return {0, ""}; }
    static Chain b() { return {1, "b."}; }
};

// The graph's topology: what a pass reads and writes for the current settings.
struct PassDecl {
    std::vector<std::string> reads;
    std::vector<ResourceDesc> writes;
};

class PassBuilder {
  public:
    explicit PassBuilder(PassDecl& d) : d_(d) {}
    void read(const std::string& resource) { d_.reads.push_back(resource); }
    void write(ResourceDesc desc) { d_.writes.push_back(std::move(desc)); }

  private:
    PassDecl& d_;
};

// What the frame is drawn from (the camera has its fitted clip planes). Passes read it only
// through their config (graph/pass_config.h).
struct FrameInfo {
    const GpuScene* scene = nullptr;
    unsigned sceneVersion = 0;
    float sceneRadius = 1.0f; // half the bounding-box diagonal, scene units
    const Camera* camera = nullptr;
    int width = 0, height = 0; // base size: the G-buffer's
    // Render pixels per displayed pixel (below 1 while the app renders reduced as the camera
    // moves): a radius in pixels means displayed pixels.
    float displayScale = 1.0f;
    // Temporal accumulation: this frame's index since the last change (0 = start over), and
    // whether the history must be dropped entirely (settings, size or scene changed).
    int temporalFrame = 0;
    bool temporalReset = true;
    // The frame constant block bound at SSAO_UBO_FRAME for every pass (Renderer::render).
    gpu::FrameConstants constants{};
    // The level of the scene's clustered copies the G-buffer draws (scene/gpu/motion_lod.h; -1: the
    // scene): the camera is moving, skip.motion_lod is on, and it is the coarsest level whose cell
    // covers at most a pixel of this frame (Renderer::setMoving) at the nearest depth of any draw;
    // each draw may take a coarser one at its own (DrawOptions::lod).
    int lod = -1;
};

// The frame constants a pass's shaders read when they do not read the temporal frame index
// (clip.w): the G-buffer and the composite must not re-run for every accumulated frame.
gpu::FrameConstants withoutFrameIndex(gpu::FrameConstants c);

// Handed to execute(): the pass's config, inputs and outputs by the names it declared.
class PassContext {
  public:
    PassContext(FrameGraph& g, const ConfigKey& config, const GpuScene* scene, gl::ShaderLibrary& sh,
                const gl::FullscreenTriangle& tri, const std::string& pass)
        : shaders(sh), graph_(g), config_(config), scene_(scene), triangle_(tri), pass_(pass) {}
    gl::ShaderLibrary& shaders;

    const ConfigKey& config() const { return config_; }
    const GpuScene* scene() const { return scene_; } // what the G-buffer draws (its version is in its config)
    const gl::Texture2D& in(const std::string& name) const;
    const ResourceDesc& desc(const std::string& name) const;
    // Binds a framebuffer with these outputs as colour attachments 0..n-1 (a depth-format output
    // becomes the depth attachment) and sets the viewport to their size.
    void bindOutputs(const std::vector<std::string>& names) const;
    // Whether anything reads this output this frame (a live pass or a consumer outside the graph:
    // FrameGraph::setWanted). A pass may leave an output nobody needs unwritten and say so; the
    // graph runs it again when that output is wanted.
    bool needed(const std::string& output) const;
    void leaveUnwritten(const std::string& output) const;
    glm::ivec2 size(const std::string& name) const;
    void drawFullscreen() const;

  private:
    FrameGraph& graph_;
    const ConfigKey& config_;
    const GpuScene* scene_;
    const gl::FullscreenTriangle& triangle_;
    std::string pass_;
};

class Pass {
  public:
    Pass(std::string name, Chain chain) : name_(std::move(name)), chain_(std::move(chain)) {}
    virtual ~Pass() = default;
    Pass(const Pass&) = delete;
    Pass& operator=(const Pass&) = delete;

    const std::string& name() const { return name_; } // unique in the graph ("ao", "b.ao")
    const Chain& chain() const { return chain_; }
    // The topology for these settings: what it reads and writes.
    virtual void setup(PassBuilder& b, const Settings& s) const = 0;
    // Its config for these settings and this frame (pure); the graph re-runs the pass when it, the
    // versions of what it reads or its external data change, and at no other time.
    virtual ConfigKey configure(const Settings& s, const FrameInfo& f) const = 0;
    virtual void execute(PassContext& ctx) = 0;
    // Data from outside the graph that the pass's output depends on (a CPU image it uploads): the
    // graph re-runs the pass when this changes, as it does for a changed input. 0 = none.
    virtual uint64_t externalVersion() const { return 0; }
    // What the last run did, for metrics.json (e.g. draws culled): name → value.
    virtual std::vector<std::pair<std::string, double>> counters() const { return {}; }
    // The sample inspector: re-runs the pass's own shader for one pixel of its output, compiled
    // with INSPECT, and returns what it recorded. Passes without taps return false.
    virtual bool inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) {
        (void)ctx, (void)pixel, (void)out;
        return false;
    }

  private:
    std::string name_;
    Chain chain_;
};

// A pass with a typed config: config() is the pure function, run() gets its result.
template <class Config> class ConfiguredPass : public Pass {
  public:
    using Pass::Pass;
    virtual Config config(const Settings& s, const FrameInfo& f) const = 0;
    ConfigKey configure(const Settings& s, const FrameInfo& f) const final { return ConfigKey::of(config(s, f)); }
    void execute(PassContext& ctx) final { run(ctx, ctx.config().as<Config>()); }

  protected:
    virtual void run(PassContext& ctx, const Config& c) = 0;
};

} // namespace ssao
