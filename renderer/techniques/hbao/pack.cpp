#include "techniques/hbao/pack.h"

#include <algorithm>

namespace ssao {

gpu::HbaoConstants packHbaoConstants(const HbaoSettings& s, const gpu::AoCommon& common, bool normalUnorm) {
    gpu::HbaoConstants c{};
    c.aoCommon = common;
    c.params = {std::clamp(s.tangentBias, 0.0f, 0.9f), std::max(s.maxRadiusPx, 2.0f), 0.0f, 0.0f};
    int flags = 0;
    packNoise(c.aoCommon, s.noise);
    c.aoCommon.shape.w = s.pyramid ? 3.0f : 0.0f; // taps d px away read MIP log2(d) - this (as SAO)
    if (s.noise != AoNoise::None) flags |= HBAO_FLAG_NOISE;
    if (normalUnorm) flags |= HBAO_FLAG_NORMAL_UNORM;
    c.modes = {std::clamp(s.directions, 1, HBAO_MAX_DIRECTIONS), std::clamp(s.steps, 1, HBAO_MAX_STEPS),
               flags, 0};
    return c;
}

} // namespace ssao
