// Denoise settings → the 1-D kernel of one separable pass (pure, tested without a GPU).
#pragma once
#include "settings/settings.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

// Direction 0 = x, 1 = y. Box4 → taps -2..1, weight 1/4 (seed 004); Box4Centred → taps at
// -1.5, -0.5, 0.5, 1.5 (read bilinearly: the DenoisePass binds a linear sampler); gaussian → taps -r..r at
// `spacing` pixels, weights exp(-i²/(2σ²)) normalised; none → the centre tap (a copy).
// skipSky: this pass returns 1 on sky pixels without filtering (only the last pass: the x pass's
// values at sky pixels feed the y pass's neighbours).
gpu::DenoiseConstants packDenoiseConstants(const DenoiseSettings& d, int direction, bool skipSky = false);

// Bilateral: taps = (half-width clamped to 8, unused, flags, unused); offsetsWeights[0] =
// (sigma, depth sharpness, normal power, unused). Flags: SSAO_DENOISE_NORMAL_UNORM.
gpu::DenoiseConstants packBilateralConstants(const DenoiseSettings& d, bool normalUnorm);

} // namespace ssao
