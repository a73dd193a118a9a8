// The second depth layer (gbuffer.second_layer): per pixel, the view-space position of the nearest
// surface facing the camera that lies at least a minimum separation behind the one the G-buffer
// shows - what the depth buffer hides, as Mara, McGuire, Nowrouzezahrai and Luebke's deep G-buffer
// (HPG 2016) keeps it, here by depth peeling against this frame's own first layer (their exact
// two-pass form). Facing is judged by the interpolated normal, as the back-face layer does. It is
// stored as a linear depth (0 where none), one channel to fetch per tap: a tap at a pixel centre
// gets the point back exactly from its uv (position_taps.glsl aoSecondLayerAt). The bitmask marks
// its sectors too (vbao.frag).
#pragma once
#include "graph/gbuffer_layers.h"
#include "graph/pass.h"
#include "scene/gpu/gpu_scene.h"
#include "settings/settings.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct SecondLayerConfig {
    gpu::FrameConstants frame; // without the temporal frame index
    float separation;          // scene units
    int32_t cull;
    int32_t hiddenFaces; // skip.hidden_faces: the sides closed shells hide face away, which it drops anyway
    uint32_t sceneVersion;
};
SSAO_CONFIG_END

class SecondLayerPass final : public ConfiguredPass<SecondLayerConfig> {
  public:
    static constexpr const char* kOutput = gbuffer::kSecondLayer;
    static bool on(const Settings& s) {
        return s.gbuffer.secondLayer && s.gbuffer.secondLayerBuild == SecondLayerBuild::Peel;
    }
    SecondLayerPass() : ConfiguredPass("second_layer", Chain::a()) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    SecondLayerConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    void run(PassContext& ctx, const SecondLayerConfig& c) override;
};

// gbuffer.second_layer as either build writes it: 1 / linear depth (0 = none), one channel.
ResourceDesc secondLayerResource();
// gbuffer.second_layer_separation in scene units (a fraction of the diagonal).
float secondLayerSeparation(const Settings& s, const FrameInfo& f);

} // namespace ssao
