// The denoise stage's temporal step (shaders/passes/temporal.frag): blends this frame's denoised
// AO with the reprojected history, then writes the result back as ao.denoised, so every consumer
// (composite, metrics, views) sees the accumulated AO. Owns the two history targets (ping-pong)
// and the previous frame's camera.
#pragma once
#include "gl/resources.h"
#include "graph/pass.h"
#include "settings/settings.h"

#include <glm/glm.hpp>

#include <string>

namespace ssao {

SSAO_CONFIG_BEGIN
// What accumulation depends on (part of the denoise pass's config; all 0 when off).
struct TemporalConfig {
    gpu::FrameConstants frame; // this frame's camera (reprojection) and frame index (new noise each)
    int32_t enabled;
    int32_t reset; // drop the history (settings, size or scene changed)
    float frames;  // running mean over this many frames
    float planeTolerance; // pixel footprints (temporal.plane_tolerance)
    float movingFrames;   // the running mean's length while the camera moves
    int32_t staticNoise;  // the AO's noise is the same every frame: nothing to average
    int32_t normalUnorm;  // gbuffer.normal holds (n + 1) / 2
};
SSAO_CONFIG_END

TemporalConfig temporalConfig(const Settings& s, const FrameInfo& f);

class TemporalAccumulator {
  public:
    // `ao`: the resource holding this frame's denoised AO, overwritten with the accumulated one.
    void run(PassContext& ctx, const TemporalConfig& c, const std::string& ao, const std::string& passName);

  private:
    gl::RenderTarget history_[2];
    int current_ = 0; // index of the latest history
    glm::mat4 prevViewProj_{1.0f}, prevView_{1.0f};
    glm::vec4 prevLens_{1.0f, 1.0f, 0.0f, 0.0f}; // the previous frame's inverse projection scale, orthographic
    bool valid_ = false; // a history of this size exists
};

} // namespace ssao
