// GTAO's constant block, shared by C++ (renderer/techniques/gtao/pack.h) and GLSL (gtao.frag).
// Both include bindings.h first (the shader loader inlines every #include line, so this file
// includes nothing itself).
#ifndef SSAOLAB_GTAO_LAYOUT_H
#define SSAOLAB_GTAO_LAYOUT_H
#ifndef SSAOLAB_BINDINGS_H
#error "include shaders/include/bindings.h before this file"
#endif
#ifdef __cplusplus
namespace ssao::gpu {
#endif

#define GTAO_MAX_SLICES 16
#define GTAO_MAX_STEPS 32

SSAO_STRUCT GtaoConstants_ {
    AoCommon_ aoCommon; // radius, power, target size (first in every technique's block)
    vec4 search; // x: radius multiplier, y/z: falloff mul/add in units of the search radius,
                 // w: step distribution power
    vec4 thin;   // x: thin-occluder compensation, y: smallest first step (pixels), zw: unused
    ivec4 modes;  // slices, steps per side, unused, unused
};

#ifdef __cplusplus
using GtaoConstants = GtaoConstants_;
static_assert(sizeof(GtaoConstants) == sizeof(AoCommon) + 3 * 16, "std140 layout");
} // namespace ssao::gpu
#endif
#endif
