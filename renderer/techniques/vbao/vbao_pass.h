// The visibility-bitmask pass: one constant block (pack.h) and one shader over the G-buffer's
// positions and normals, writing ao.raw (techniques/ao_pass.h).
#pragma once
#include "techniques/ao_pass.h"
#include "techniques/vbao/pack.h"

namespace ssao {

struct VbaoTraits {
    using Constants = gpu::VbaoConstants;
    static constexpr const char* group = "vbao";
    static constexpr const char* shader = "techniques/vbao/vbao.frag";
    static Constants pack(const Settings& s, const gpu::AoCommon& common, bool normalUnorm) {
        return packVbaoConstants(s.vbao, common, normalUnorm);
    }
};
using VbaoPass = OneBlockPass<VbaoTraits>;

} // namespace ssao
