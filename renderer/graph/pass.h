// A pass is a small class with declared inputs and outputs. setup() declares, for the current
// settings, which resources it reads and writes, which parameter groups it depends on and whether
// it reads the scene or the camera; the frame graph orders passes from those declarations and
// re-runs a pass only when one of them changed (filament's frame graph, reduced to our needs).
#pragma once
#include "graph/inspection.h"
#include "graph/resource.h"
#include "settings/settings.h"

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

// Which AO chain a pass belongs to: A (the main one, unprefixed names) or B (the split view's
// second chain, names prefixed "b."). Both share the G-buffer.
struct Branch {
    int index = 0;
    std::string prefix; // "" or "b."
    std::string res(const std::string& name) const { return prefix + name; }
    static Branch a() { return {0, ""}; }
    static Branch b() { return {1, "b."}; }
};

struct PassDecl {
    std::vector<std::string> reads;
    std::vector<ResourceDesc> writes;
    std::vector<std::string> groups; // parameter-table groups (or "group.row") whose values key this pass
    bool scene = false, camera = false;
    bool frameIndex = false; // its noise follows the temporal frame index (frame.clip.w)
};

class PassBuilder {
  public:
    explicit PassBuilder(PassDecl& d) : d_(d) {}
    void read(const std::string& resource) { d_.reads.push_back(resource); }
    void write(ResourceDesc desc) { d_.writes.push_back(std::move(desc)); }
    // A parameter-table group ("ao": the pass re-runs when any of its rows changes), or one row of
    // it ("skip.sky": only that row).
    void settings(const std::string& group) { d_.groups.push_back(group); }
    void usesScene() { d_.scene = true; }
    void usesCamera() { d_.camera = true; }
    void usesFrameIndex() { d_.frameIndex = true; }

  private:
    PassDecl& d_;
};

// What the frame is drawn from (the camera has its fitted clip planes).
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
};

// Handed to execute(): the pass's settings, inputs and outputs by the names it declared.
class PassContext {
  public:
    PassContext(FrameGraph& g, const Settings& s, const FrameInfo& f, gl::ShaderLibrary& sh,
                const gl::FullscreenTriangle& tri, const std::string& pass)
        : settings(s), frame(f), shaders(sh), graph_(g), triangle_(tri), pass_(pass) {}
    const Settings& settings;
    const FrameInfo& frame;
    gl::ShaderLibrary& shaders;

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
    const gl::FullscreenTriangle& triangle_;
    std::string pass_;
};

class Pass {
  public:
    Pass(std::string name, Branch branch) : name_(std::move(name)), branch_(std::move(branch)) {}
    virtual ~Pass() = default;
    Pass(const Pass&) = delete;
    Pass& operator=(const Pass&) = delete;

    const std::string& name() const { return name_; } // unique in the graph ("ssao", "b.ssao")
    const Branch& branch() const { return branch_; }
    virtual void setup(PassBuilder& b, const Settings& s) const = 0;
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
    Branch branch_;
};

} // namespace ssao
