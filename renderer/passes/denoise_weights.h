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

// Bilateral: taps = (half-width clamped to 8, k below, flags, unused); offsetsWeights[0] =
// (sigma, depth sharpness, normal power, unused). Flags: SSAO_DENOISE_NORMAL_UNORM.
// taps.y = k > 0: the filter runs at the AO's resolution, 1/k of the G-buffer's, and reads the
// G-buffer texel each AO texel was computed at (t·k); 0: output at the G-buffer's resolution.
gpu::DenoiseConstants packBilateralConstants(const DenoiseSettings& d, bool normalUnorm, int k = 0);

// The joint 2x2 upsample (passes/upsample_joint.frag): taps.w = the relative depth tolerance
// added to the local slope's, in thousandths of the pixel's depth (10: 1 %).
gpu::DenoiseConstants packJointUpsampleConstants();

} // namespace ssao
