// Kernel SSAO's constant block, shared by C++ (renderer/techniques/kernel/pack.h) and GLSL
// (kernel.frag). Both include bindings.h first (the shader loader inlines every #include line,
// so this file includes nothing itself).
#ifndef SSAOLAB_KERNEL_LAYOUT_H
#define SSAOLAB_KERNEL_LAYOUT_H
#ifndef SSAOLAB_BINDINGS_H
#error "include shaders/include/bindings.h before this file"
#endif
#ifdef __cplusplus
namespace ssao::gpu {
#endif

#define KERNEL_MAX_SAMPLES 256
#define KERNEL_TEX_NOISE (SSAO_TEX_TECHNIQUE + 0) // 4x4 rotation-noise tile

#define KERNEL_RANGE_SMOOTHSTEP 0
#define KERNEL_RANGE_HARD 1
#define KERNEL_RANGE_OFF 2
#define KERNEL_DEPTHTEST_SAMPLE 0   // seeds 000/004: sceneZ >= sample.z + bias
#define KERNEL_DEPTHTEST_FRAGMENT 1 // seed 003: fragment.z + bias < sceneZ
#define KERNEL_FLAG_SEPARABLE 1
#define KERNEL_FLAG_NOISE 2
#define KERNEL_FLAG_POS_FROM_DEPTH 4
#define KERNEL_FLAG_OFFSCREEN_CLAMP 8 // seeds: clamp-to-edge; else off-screen samples count as open
#define KERNEL_FLAG_OWN_TEXEL_OPEN 32 // a sample reading its own pixel's texel counts as open

SSAO_STRUCT KernelConstants_ {
    AoCommon_ aoCommon; // radius, power, target size (first in every technique's block)
    vec4 params;     // x: bias, y: range-check |dz| floor, both as fractions of the radius
    vec4 noiseScale; // xy: AO target size / 4 (noise tiles), zw: unused
    ivec4 modes;     // sampleCount, range check, depth test, flags
    vec4 kernel[2 * KERNEL_MAX_SAMPLES]; // [0,N): main (or x-plane) set, [256,256+N): y-plane set
};

#ifdef __cplusplus
using KernelConstants = KernelConstants_;
static_assert(sizeof(KernelConstants) == sizeof(AoCommon) + 3 * 16 + 2 * KERNEL_MAX_SAMPLES * 16, "std140 layout");
} // namespace ssao::gpu
#endif
#endif
