// The guard band (gbuffer.guard_band_px = g > 0): the view-space positions of the frame and g
// pixels beyond each of its edges, on the same pixel grid (pixel (x, y) of the frame is (x + g,
// y + g) here), so AO taps that leave the frame still find what is just outside it (Bavoil and
// Sainz 2008; McGuire et al.'s deep G-buffer demos use 64 px). AO passes read it only for taps off
// the frame (shaders/include/position_taps.glsl aoTapHeld); everything else keeps reading the
// frame-sized G-buffer. This draws the scene a second time with the frustum widened by the band:
// a renderer that drew its G-buffer once at the larger size would pay only the band's pixels.
#pragma once
#include "graph/gbuffer_layers.h"
#include "graph/pass.h"
#include "scene/gpu/gpu_scene.h"
#include "settings/settings.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct GuardBandConfig {
    gpu::FrameConstants frame; // the frame's, with the projection widened by the band
    int32_t band;              // pixels beyond each edge
    int32_t cull;              // skip.cull: draws outside the widened view are not issued
    int32_t hiddenFaces;       // skip.hidden_faces: closed shells' hidden sides are culled
    uint32_t sceneVersion;
};
SSAO_CONFIG_END

// The projection that draws a width x height frame's pixel grid over (width + 2 band) x (height +
// 2 band) pixels: x and y in clip space scaled by width / (width + 2 band), height likewise.
glm::mat4 widenedProjection(const glm::mat4& proj, int width, int height, int band);

class GuardBandPass final : public ConfiguredPass<GuardBandConfig> {
  public:
    static constexpr const char* kOutput = gbuffer::kGuardBand;
    // The band of these settings' G-buffer (0: no band, the pass is not in the graph).
    static int bandOf(const Settings& s) { return s.gbuffer.guardBandPx; }
    explicit GuardBandPass(int band) : ConfiguredPass("guard_band", Chain::a()), band_(band) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    GuardBandConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    void run(PassContext& ctx, const GuardBandConfig& c) override;
    gl::UniformBuffer frameUbo_{sizeof(gpu::FrameConstants), "guard_band.frame"};
    int band_;
};

} // namespace ssao
