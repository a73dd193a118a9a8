// Scalable Ambient Obscurance (McGuire, Mara, Luebke 2012; the Alchemy AO estimator of McGuire et
// al. 2011): N taps on a spiral around the pixel, each adding max(0, v·n - bias) / (v·v + ε) with
// the recommended falloff (1 - v·v/R²)³, in units of the radius so it behaves the same at any
// scene scale. An obscurance (falloff-weighted), not binary visibility.
#pragma once
#include "techniques/noise/noise.h"

namespace ssao {

using SaoNoise = AoNoise; // shared with every horizon technique (techniques/noise/noise.h)

struct SaoSettings {
    int samples = 11;       // taps (the SAO paper's 11)
    float turns = 7.0f;     // spiral turns over the taps (SAO: 7 for 11 taps)
    float intensity = 1.0f; // σ of Alchemy AO: scales the summed obscurance
    float bias = 0.012f;    // β: v·n must exceed this fraction of R (SAO's 0.012 at R = 1)
    SaoNoise noise = SaoNoise::Ign;
    bool pyramid = false; // far taps read the position pyramid (passes/position_pyramid_pass.h): off,
                          // on llvmpipe it costs time for the same error (docs/bench/report.md)
};

} // namespace ssao
