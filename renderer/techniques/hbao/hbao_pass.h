// HBAO's pass: one constant block (pack.h) and one shader over the G-buffer's positions and
// normals, writing ao.raw (techniques/ao_pass.h).
#pragma once
#include "techniques/ao_pass.h"
#include "techniques/hbao/pack.h"

namespace ssao {

struct HbaoTraits {
    using Constants = gpu::HbaoConstants;
    static constexpr const char* group = "hbao";
    static constexpr const char* shader = "techniques/hbao/hbao.frag";
    static Constants pack(const Settings& s, const gpu::AoCommon& common, bool normalUnorm) {
        return packHbaoConstants(s.hbao, common, normalUnorm);
    }
};
using HbaoPass = OneBlockPass<HbaoTraits>;

} // namespace ssao
