// Horizon-Based AO (Bavoil, Sainz, Dimitrov 2008, "Image-Space Horizon-Based Ambient Occlusion";
// seed 002): D screen directions around the pixel, S steps along each, the highest horizon above
// the tangent plane per direction, occlusion = the rise of sin(horizon) weighted by a linear
// falloff W = max(0, 1 - r/R) (the per-sample attenuation of HBAO+), uniform in solid angle.
#pragma once
#include "techniques/noise/noise.h"

namespace ssao {

using HbaoNoise = AoNoise; // shared with every horizon technique (techniques/noise/noise.h)

struct HbaoSettings {
    int directions = 8;         // D
    int steps = 4;              // S per direction
    float tangentBias = 0.1f;   // sin of the bias angle above the tangent plane (~6 degrees)
    float maxRadiusPx = 128.0f; // the projected radius is clamped to this many pixels (cache, cost)
    HbaoNoise noise = HbaoNoise::Ign;
    bool pyramid = false; // far taps read the position pyramid (passes/position_pyramid_pass.h): off,
                          // on llvmpipe it costs time for the same error (docs/bench/report.md)
};

} // namespace ssao
