// HBAO's constant block, shared by C++ (renderer/techniques/hbao/pack.h) and GLSL (hbao.frag).
// Both include bindings.h first (the shader loader inlines every #include line, so this file
// includes nothing itself).
#ifndef SSAOLAB_HBAO_LAYOUT_H
#define SSAOLAB_HBAO_LAYOUT_H
#ifndef SSAOLAB_BINDINGS_H
#error "include shaders/include/bindings.h before this file"
#endif
#ifdef __cplusplus
namespace ssao::gpu {
#endif

#define HBAO_MAX_DIRECTIONS 32
#define HBAO_MAX_STEPS 32

SSAO_STRUCT HbaoConstants_ {
    AoCommon_ aoCommon; // radius, power, target size (first in every technique's block)
    vec4 params;        // x: tangent bias (sin of the angle), y: max radius in pixels, zw: unused
    ivec4 modes;        // directions, steps, unused, unused
};

#ifdef __cplusplus
using HbaoConstants = HbaoConstants_;
static_assert(sizeof(HbaoConstants) == sizeof(AoCommon) + 2 * 16, "std140 layout");
} // namespace ssao::gpu
#endif
#endif
