// GTAO's pass: one constant block (pack.h) and one shader over the G-buffer's positions and
// normals, writing ao.raw (techniques/ao_pass.h).
#pragma once
#include "techniques/ao_pass.h"
#include "techniques/gtao/pack.h"

namespace ssao {

struct GtaoTraits {
    using Constants = gpu::GtaoConstants;
    static constexpr const char* group = "gtao";
    static constexpr const char* shader = "techniques/gtao/gtao.frag";
    static Constants pack(const Settings& s, const gpu::AoCommon& common, bool normalUnorm) {
        return packGtaoConstants(s.gtao, common, normalUnorm);
    }
};
using GtaoPass = OneBlockPass<GtaoTraits>;

} // namespace ssao
