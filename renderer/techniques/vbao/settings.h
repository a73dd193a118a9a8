// Visibility-bitmask AO (Therrien, Levesque, Gilet 2023, "Screen Space Indirect Lighting with
// Visibility Bitmask"): GTAO's slices, but each depth sample occludes only the sectors of the
// slice between its front face and its back face (the front pushed back by an assumed thickness),
// recorded as bits of a 32-sector mask. Light passing behind a thin object is no longer blocked, as
// it is by a horizon, which treats everything below it as solid. The unoccluded sectors are
// integrated with GTAO's cosine weighting, so an empty mask gives exactly GTAO's open value.
#pragma once
#include "techniques/noise/noise.h"

namespace ssao {

struct VbaoSettings {
    int slices = 4;                 // directions around the view vector
    int steps = 8;                  // depth samples per side of a slice
    float thickness = 1.0f;         // assumed depth of every surface, in units of the AO radius
    float distributionPower = 2.0f; // step k of n at (k/n)^p of the radius, denser near the pixel
    // Where the back-face layer (gbuffer.back_faces) holds a surface's far side, its sectors end
    // there even when that is thinner than `thickness`; off: never less than the assumed depth.
    bool trueThickness = false;
    AoNoise noise = AoNoise::Ign;
    bool pyramid = false; // far taps read the position pyramid (passes/position_pyramid_pass.h): off,
                          // on llvmpipe it costs time for the same error (docs/bench/report.md)
};

} // namespace ssao
