#include "techniques/hbao/pack.h"

namespace ssao {

gpu::HbaoConstants packHbaoConstants(const HbaoSettings& s, const gpu::AoCommon& common) {
    gpu::HbaoConstants c{};
    c.aoCommon = common;
    c.params = {s.tangentBias, s.maxRadiusPx, 0.0f, 0.0f};
    c.modes = {s.directions, s.steps, 0, 0};
    return c;
}

} // namespace ssao
