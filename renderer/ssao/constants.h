// Settings → GPU constants: the one pure function between what a person sets and the std140
// blocks the shaders read (XeGTAO's GTAOUpdateConstants pattern). Tested without a GPU.
#pragma once
#include "scene/camera.h"
#include "settings/settings.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

gpu::FrameConstants packFrameConstants(const Camera& cam, int width, int height, float sceneRadius);
gpu::SsaoConstants packSsaoConstants(const SsaoSettings& s, const GBufferSettings& g, int width, int height);
// One 1-D pass of the separable blur (direction 0 = x, 1 = y). Box4 → taps -2..1, weight 1/4
// (seed 004); gaussian → taps -r..r at `spacing` pixels, weights exp(-i²/(2σ²)) normalised.
gpu::BlurConstants packBlurConstants(const BlurSettings& b, int direction);

} // namespace ssao
