// The SSAO renderer: a frame graph of the G-buffer pass, the chosen AO technique, the denoise
// stage and the composite — plus, for the split view, a second AO chain "b." with its own settings
// that shares the G-buffer (and any pass whose settings and inputs equal the first chain's).
#pragma once
#include "gl/frame_watchdog.h"
#include "gl/shader_library.h"
#include "graph/frame_graph.h"
#include "passes/reference_pass.h"
#include "scene/camera.h"
#include "scene/gpu/gpu_scene.h"
#include "techniques/ao_common.h"

#include "../shaders/include/bindings.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ssao {

// Render sizes: the G-buffer alone takes ~60 bytes a pixel, so 16.7 million pixels is ~1 GB.
constexpr int kMaxRenderSide = 16384;
constexpr long kMaxRenderPixels = 4096L * 4096L;
// Throws ssao::Error naming the size and the limits when it is not renderable.
void checkRenderSize(int width, int height);

// Camera and size → the per-frame constant block every shader reads (pure).
// `frameIndex`: the temporal accumulation's frame (per-frame noise offsets; 0 otherwise).
gpu::FrameConstants packFrameConstants(const Camera& cam, int width, int height, float sceneRadius,
                                       int frameIndex = 0);

class Renderer {
  public:
    explicit Renderer(const std::string& shaderDir);
    ~Renderer();

    void setScene(const Scene& scene);
    void setCamera(const Camera& camera); // clip planes fitted per frame unless camera.clip is Fixed
    void setSettings(const Settings& settings);
    void setSettingsB(std::optional<Settings> settings); // chain B on (the split view) or off
    void setSize(int width, int height);
    // Render pixels per displayed pixel (the app renders reduced while the camera moves): a radius
    // in pixels is a radius in displayed pixels. 1 headless.
    void setDisplayScale(float scale);
    // The widest any view shows the final image (pixels; 0, the default: as rendered): the
    // composite, which no pass reads, is drawn at that size (CompositePass::setDisplayWidth; the
    // app's grid cell).
    void setDisplayWidth(int px);
    // Frames drawn while the camera moves (the app; false headless): with skip.motion_lod the
    // G-buffer draws the scene's clustered copy where one cell of it covers at most a pixel of the
    // frame (scene/gpu/motion_lod.h). The still frame after it draws the full mesh.
    void setMoving(bool moving) { moving_ = moving; }
    // The clustered level the last render() drew (-1: the scene's own triangles).
    int drewLod() const { return frame_.lod; }
    const GpuScene* gpuScene() const { return scene_.get(); } // null before setScene
    // Build the clustered copies of the scenes set from now on (the app; headless renders never move).
    void enableMotionLods() { motionLods_ = true; }
    // The ray-traced reference as two more buffers, reference.ao and reference.error
    // (passes/reference_pass.h), uploaded when `buffers` has a new version; null (the default, and
    // headless) takes them out of the graph.
    void setReferenceBuffers(std::shared_ptr<const ReferenceBuffers> buffers);
    // The buffers read after render() (shown, saved, judged); nullopt (the default) = all. Passes
    // that feed none of them are culled, and the G-buffer leaves out targets nothing reads
    // (skip.unused_targets). gbuffer.depth is always kept (radiusAtCentre reads it).
    void setWanted(std::optional<std::set<std::string>> buffers);
    // Headless runs only: a render() whose GL work has not finished `seconds` after it began ends
    // the process with one error line (gl/frame_watchdog.h). 0, the default (the explorer): no limit.
    void setFrameTimeLimit(double seconds);
    // Forces every pass to run on the next frame (e.g. for timing all passes).
    void invalidate() { graph_.invalidate(); }

    FrameReport render();
    // Temporal accumulation on and fewer than temporal.frames frames blended since the last change:
    // render() again (the app keeps drawing, headless renders that many frames).
    bool accumulating() const;

    const Settings& settings() const { return settings_; }
    const std::optional<Settings>& settingsB() const { return settingsB_; }
    const Camera& camera() const { return effective_; } // as rendered: fitted near/far
    const Camera& userCamera() const { return camera_; }
    int width() const { return width_; }
    int height() const { return height_; }
    const Bounds& bounds() const { return bounds_; }
    float sceneRadius() const { return bounds_.valid() ? bounds_.radius() : 1.0f; }
    unsigned sceneVersion() const { return sceneVersion_; }

    const FrameGraph& graph() const { return graph_; }
    // What the last render() drew from (camera, size, frame constants): the passes' configs are
    // pure functions of it and the settings.
    const FrameInfo& frame() const { return frame_; }
    // The texture of a resource ("gbuffer.depth", "ao.raw", "b.composite", ...); throws if unknown.
    const gl::Texture2D& texture(const std::string& resource) const { return graph_.get(resource).texture; }
    const Resource& resource(const std::string& name) const { return graph_.get(name); }
    // Chain A's and the shared buffers in production order (what the grid, EXR/PNG and metrics list).
    std::vector<const Resource*> buffers() const;
    // GPU sample inspector for chain `chain` (0 = A, 1 = B) at a pixel of the G-buffer resolution
    // (y from the top); nullopt when the technique records no taps or the pixel is outside.
    std::optional<PixelInspection> inspect(int chain, glm::ivec2 pixel);

    // Radius in displayed pixels (see setDisplayScale); reads one texel of gbuffer.depth.
    RadiusInfo radiusAtCentre() const;

    gl::ShaderLibrary& shaders() { return shaders_; }
    const gl::FullscreenTriangle& triangle() const { return triangle_; }
    void drawFullscreen() const { triangle_.draw(); }

  private:
    void buildGraph();
    std::vector<Pass*> techniquePasses(const Chain& c, const Settings& s);
    std::vector<Pass*> chainPasses(const Chain& c, const Settings& s); // technique, denoise, composite
    // Per chain-B pass: whether it equals chain A's this frame (its outputs then alias A's); fills
    // `aliases` when given.
    std::vector<bool> sharedWithChainA(std::map<std::string, std::string>* aliases);
    Pass& passFor(const std::string& key, const std::function<std::unique_ptr<Pass>()>& make);

    gl::ShaderLibrary shaders_;
    gl::FullscreenTriangle triangle_;
    gl::UniformBuffer frameUbo_;
    std::unique_ptr<GpuScene> scene_;
    Bounds bounds_;
    unsigned sceneVersion_ = 0;
    Camera camera_, effective_;
    Settings settings_;
    std::optional<Settings> settingsB_;
    // The shared G-buffer's settings: chain A's, with the second layer of the chain that has one
    // (A's first), so either chain's layer is built (buildGraph).
    Settings gbufferSettings_;
    int width_ = 0, height_ = 0;
    float displayScale_ = 1.0f;
    bool moving_ = false, motionLods_ = false;
    FrameGraph graph_;
    bool graphStale_ = true; // settings, chain B, size or reference on/off changed since compile()
    // Per chain (A, B): nothing outside the graph wants its ao.denoised, so its composite may
    // upsample reduced AO inline (CompositePass::allowFusedUpsample).
    bool fuseA_ = false, fuseB_ = false;
    int displayWidth_ = 0; // setDisplayWidth
    int temporalFrame_ = 0;  // frames accumulated since the camera or the settings changed
    // What the accumulated history was made with: settings, size or scene differing drop it; a
    // different camera only restarts the count (compared directly, not serialised, every frame).
    std::optional<Settings> temporalSettings_;
    Camera temporalCamera_;
    glm::ivec2 temporalSize_{0};
    unsigned temporalScene_ = 0;
    FrameInfo frame_;
    std::map<std::string, std::unique_ptr<Pass>> passes_; // kept across rebuilds (they own GL state)
    ReferencePass referencePass_;
    bool referenceOn_ = false;
    std::vector<bool> sharedB_; // sharedWithChainA() when the graph was built
    std::map<std::string, std::vector<std::unique_ptr<Pass>>> techniquePasses_; // by chain + technique
    unsigned techniquesGeneration_ = 0; // of the registry (techniques/technique.h) the graph was built with
    std::unique_ptr<gl::FrameWatchdog> watchdog_; // setFrameTimeLimit; null: no limit
};

} // namespace ssao
