// SAO's constant block, shared by C++ (renderer/techniques/sao/pack.h) and GLSL (sao.frag).
// Both include bindings.h first (the shader loader inlines every #include line, so this file
// includes nothing itself).
#ifndef SSAOLAB_SAO_LAYOUT_H
#define SSAOLAB_SAO_LAYOUT_H
#ifndef SSAOLAB_BINDINGS_H
#error "include shaders/include/bindings.h before this file"
#endif
#ifdef __cplusplus
namespace ssao::gpu {
#endif

#define SAO_MAX_SAMPLES 64

SSAO_STRUCT SaoConstants_ {
    AoCommon_ aoCommon; // radius, power, target size (first in every technique's block)
    vec4 params;        // x: spiral turns, y: 2 intensity / N, z: bias (x R), w: epsilon (x R²)
    ivec4 modes;        // samples, unused, unused, unused
};

#ifdef __cplusplus
using SaoConstants = SaoConstants_;
static_assert(sizeof(SaoConstants) == sizeof(AoCommon) + 2 * 16, "std140 layout");
} // namespace ssao::gpu
#endif
#endif
