#include "techniques/vbao/pack.h"

#include "techniques/ao_common.h"

namespace ssao {

gpu::VbaoConstants packVbaoConstants(const VbaoSettings& s, const gpu::AoCommon& common) {
    gpu::VbaoConstants c{};
    c.aoCommon = common;
    c.params = {s.thickness, s.distributionPower, kMinFirstStepPx, 0.0f};
    c.modes = {s.slices, s.steps, s.trueThickness ? 1 : 0, 0};
    return c;
}

} // namespace ssao
