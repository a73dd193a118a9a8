// The back-face layer (gbuffer.back_faces): per pixel, the linear depth of the nearest surface
// that faces away from the camera - for a closed object seen from outside, the far side of what
// the G-buffer shows, i.e. its true thickness along the view ray (the "back-face depth" of
// Mara, McGuire, Nowrouzezahrai and Luebke's deep G-buffer discussion, 2016). Facing is judged by
// the interpolated normal, not the winding (CAD files wind either way): a fragment whose normal
// points toward the eye is discarded. 0 where no surface faces away. The bitmask reads it for the
// sectors a tap hides (shaders/include/position_taps.glsl aoBackGap).
#pragma once
#include "graph/gbuffer_layers.h"
#include "graph/pass.h"
#include "scene/gpu/gpu_scene.h"
#include "settings/settings.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct BackFaceConfig {
    gpu::FrameConstants frame; // without the temporal frame index
    int32_t cull;
    uint32_t sceneVersion;
};
SSAO_CONFIG_END

class BackFacePass final : public ConfiguredPass<BackFaceConfig> {
  public:
    static constexpr const char* kOutput = gbuffer::kBackDepth;
    static bool on(const Settings& s) { return s.gbuffer.backFaces; }
    BackFacePass() : ConfiguredPass("back_faces", Chain::a()) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    BackFaceConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    void run(PassContext& ctx, const BackFaceConfig& c) override;
};

} // namespace ssao
