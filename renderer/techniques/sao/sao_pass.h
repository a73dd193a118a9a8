// SAO's pass: one constant block (pack.h) and one shader over the G-buffer's positions and
// normals, writing ao.raw (techniques/ao_pass.h).
#pragma once
#include "techniques/ao_pass.h"
#include "techniques/sao/pack.h"

namespace ssao {

struct SaoTraits {
    using Constants = gpu::SaoConstants;
    static constexpr const char* group = "sao";
    static constexpr const char* shader = "techniques/sao/sao.frag";
    static Constants pack(const Settings& s, const gpu::AoCommon& common, bool normalUnorm) {
        return packSaoConstants(s.sao, common, normalUnorm);
    }
};
using SaoPass = OneBlockPass<SaoTraits>;

} // namespace ssao
