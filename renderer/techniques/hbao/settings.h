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
    bool pyramid = false; // far taps read the position pyramid (techniques/position_pyramid.h): off,
                          // it cost 9-13 % on llvmpipe for the same error (docs/benchmarks.md)
};

} // namespace ssao
