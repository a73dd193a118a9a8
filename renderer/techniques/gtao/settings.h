// Ground-Truth AO (Jimenez, Wu, Pesce, Jarabo 2016, "Practical Realtime Strategies for Accurate
// Indirect Occlusion"), structured like Intel XeGTAO (its reference implementation): per pixel,
// slices through the view vector; in each, the two horizons found by marching the depth buffer;
// the cosine-weighted visibility between them integrated analytically.
#pragma once
#include "techniques/noise/noise.h"

namespace ssao {

enum class GtaoQuality { Low, Medium, High, Ultra, Custom }; // XeGTAO's presets: slices x steps
using GtaoNoise = AoNoise; // shared with every horizon technique (techniques/noise/noise.h)

struct GtaoSettings {
    GtaoQuality quality = GtaoQuality::High;
    int slices = 4;                  // custom quality only
    int steps = 8;                   // per side of each slice, custom quality only
    float radiusMultiplier = 1.457f; // XeGTAO's auto-tuned default: the search radius is R x this
    float falloffRange = 0.615f;     // fraction of the radius over which occluders fade out (XeGTAO)
    float distributionPower = 2.0f;  // steps at s^p of the radius: denser near the pixel (XeGTAO)
    float thinCompensation = 0.0f;   // thin-occluder heuristic: stretch depth deltas by (1 + t) (XeGTAO)
    GtaoNoise noise = GtaoNoise::Ign;
    bool pyramid = false; // far taps read the position pyramid (passes/position_pyramid_pass.h): off,
                          // on llvmpipe it costs time for the same error (docs/bench/report.md)
};

// Slices and steps per side of a quality level (XeGTAO vaGTAO.hlsl: Low 1x2, Medium 2x2, High 3x3,
// Ultra 9x3); custom → the settings' own.
void gtaoSlicesSteps(const GtaoSettings& s, int& slices, int& steps);

} // namespace ssao
