#include "techniques/vbao/pack.h"

#include <algorithm>

namespace ssao {

gpu::VbaoConstants packVbaoConstants(const VbaoSettings& s, const gpu::AoCommon& common, bool normalUnorm) {
    gpu::VbaoConstants c{};
    c.aoCommon = common;
    packNoise(c.aoCommon, s.noise);
    c.aoCommon.shape.w = s.pyramid ? 3.3f : 0.0f; // taps d px away read MIP log2(d) - this (as GTAO)
    c.params = {std::max(s.thickness, 0.0f), std::max(s.distributionPower, 0.1f), 1.3f /* min first step, px */,
                0.0f};
    int flags = 0;
    if (s.noise != AoNoise::None) flags |= VBAO_FLAG_NOISE;
    if (normalUnorm) flags |= VBAO_FLAG_NORMAL_UNORM;
    c.modes = {std::clamp(s.slices, 1, VBAO_MAX_SLICES), std::clamp(s.steps, 1, VBAO_MAX_STEPS), flags, 0};
    return c;
}

} // namespace ssao
