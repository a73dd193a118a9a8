#include "techniques/gtao/pack.h"

#include <algorithm>

namespace ssao {

void gtaoSlicesSteps(const GtaoSettings& s, int& slices, int& steps) {
    switch (s.quality) {
    case GtaoQuality::Low:
        slices = 1, steps = 2;
        return;
    case GtaoQuality::Medium:
        slices = 2, steps = 2;
        return;
    case GtaoQuality::High:
        slices = 3, steps = 3;
        return;
    case GtaoQuality::Ultra:
        slices = 9, steps = 3;
        return;
    case GtaoQuality::Custom:
        break;
    }
    slices = std::clamp(s.slices, 1, GTAO_MAX_SLICES);
    steps = std::clamp(s.steps, 1, GTAO_MAX_STEPS);
}

gpu::GtaoConstants packGtaoConstants(const GtaoSettings& s, const gpu::AoCommon& common, bool normalUnorm) {
    gpu::GtaoConstants c{};
    c.aoCommon = common;
    int slices = 0, steps = 0;
    gtaoSlicesSteps(s, slices, steps);
    // Falloff over the last `falloffRange` of the (multiplied) radius: weight = saturate(d * mul + add)
    // is 1 up to R (1 - range) and 0 at R (XeGTAO GTAOUpdateConstants, in units of the radius so the
    // shader scales it by the pixel's world radius).
    const float range = std::clamp(s.falloffRange, 1e-3f, 1.0f);
    const float from = 1.0f - range;
    c.params = {std::max(s.radiusMultiplier, 1e-3f), -1.0f / range, from / range + 1.0f,
                std::max(s.distributionPower, 0.1f)};
    c.params2 = {std::max(s.thinCompensation, 0.0f), 1.3f /* min first step, px */, 0.0f, 0.0f};
    int flags = 0;
    packNoise(c.aoCommon, s.noise);
    c.aoCommon.shape.w = s.pyramid ? 3.3f : 0.0f; // taps d px away read MIP log2(d) - this (XeGTAO depthMIPSamplingOffset)
    if (s.noise != AoNoise::None) flags |= GTAO_FLAG_NOISE;
    if (normalUnorm) flags |= GTAO_FLAG_NORMAL_UNORM;
    c.modes = {slices, steps, flags, 0};
    return c;
}

} // namespace ssao
