// The visibility-bitmask constant block, shared by C++ (renderer/techniques/vbao/pack.h) and GLSL
// (vbao.frag). Both include bindings.h first.
#ifndef SSAOLAB_VBAO_LAYOUT_H
#define SSAOLAB_VBAO_LAYOUT_H
#ifndef SSAOLAB_BINDINGS_H
#error "include shaders/include/bindings.h before this file"
#endif
#ifdef __cplusplus
namespace ssao::gpu {
#endif

#define VBAO_MAX_SLICES 16
#define VBAO_MAX_STEPS 32
#define VBAO_SECTORS 32          // bits of the per-slice mask (one uint)

SSAO_STRUCT VbaoConstants_ {
    AoCommon_ aoCommon; // radius, power, noise, normals, pyramid (first in every technique's block)
    vec4 params;  // x: thickness (x radius), y: step distribution power, z: smallest first step (px), w: unused
    ivec4 modes;  // slices, steps per side, 1 = true thickness (vbao.true_thickness), unused
};

#ifdef __cplusplus
using VbaoConstants = VbaoConstants_;
static_assert(sizeof(VbaoConstants) == sizeof(AoCommon) + 2 * 16, "std140 layout");
} // namespace ssao::gpu
#endif
#endif
