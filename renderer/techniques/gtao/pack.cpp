#include "techniques/gtao/pack.h"

#include "techniques/ao_common.h"

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
    slices = s.slices, steps = s.steps;
}

gpu::GtaoConstants packGtaoConstants(const GtaoSettings& s, const gpu::AoCommon& common) {
    gpu::GtaoConstants c{};
    c.aoCommon = common;
    int slices = 0, steps = 0;
    gtaoSlicesSteps(s, slices, steps);
    // Falloff over the last `falloffRange` of the (multiplied) radius: weight = saturate(d * mul + add)
    // is 1 up to R (1 - range) and 0 at R (XeGTAO GTAOUpdateConstants, in units of the radius so the
    // shader scales it by the pixel's world radius).
    const float range = s.falloffRange, from = 1.0f - range;
    c.search = {s.radiusMultiplier, -1.0f / range, from / range + 1.0f, s.distributionPower};
    c.thin = {s.thinCompensation, kMinFirstStepPx, 0.0f, 0.0f};
    c.modes = {slices, steps, 0, 0};
    return c;
}

} // namespace ssao
