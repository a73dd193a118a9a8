// Binding points and GPU constant layouts, declared once for C++ and GLSL.
// C++ includes this file directly; the shader loader inlines it into GLSL via #include.
#ifndef SSAOLAB_BINDINGS_H
#define SSAOLAB_BINDINGS_H

// ---- Texture units -------------------------------------------------------------------------
#define SSAO_TEX_POSITION 0   // G-buffer view-space position (xyz) + geometry mask (w = 1)
#define SSAO_TEX_NORMAL 1     // G-buffer view-space normal (raw or (n+1)/2 encoded)
#define SSAO_TEX_DEPTH 2      // G-buffer hardware depth (window-space [0,1])
#define SSAO_TEX_ALBEDO 3     // G-buffer base colour
#define SSAO_TEX_NOISE 4      // 4x4 rotation-noise tile
#define SSAO_TEX_AO 5         // AO input of the blur / composite passes
#define SSAO_TEX_LINEAR_DEPTH 6 // linear view distance (positive), 0 = sky
#define SSAO_TEX_VIEW_SOURCE 7  // buffer shown by the debug view pass
#define SSAO_TEX_VIEW_MASK 8    // geometry mask (position.w) for the debug view pass

// Debug view modes (debug_view.frag)
#define SSAO_VIEW_COLOR 0     // rgb as is (albedo, composite)
#define SSAO_VIEW_SIGNED 1    // x * 0.5 + 0.5 (normals)
#define SSAO_VIEW_POSITION 2  // x * scale + 0.5
#define SSAO_VIEW_SCALAR 3    // r * scale, grey (depth, AO)
#define SSAO_VIEW_UNORM_NORMAL 4 // already (n+1)/2

// ---- Uniform buffer bindings ---------------------------------------------------------------
#define SSAO_UBO_FRAME 0      // FrameConstants
#define SSAO_UBO_SSAO 1       // SsaoConstants
#define SSAO_UBO_BLUR 2       // BlurConstants

#define SSAO_MAX_SAMPLES 256
#define SSAO_MAX_BLUR_TAPS 65 // 2*32+1 taps of a 1-D kernel

// Mode values shared by packing code and shaders.
#define SSAO_RANGE_SMOOTHSTEP 0
#define SSAO_RANGE_HARD 1
#define SSAO_RANGE_OFF 2
#define SSAO_DEPTHTEST_SAMPLE 0   // seeds 000/004: sceneZ >= sample.z + bias
#define SSAO_DEPTHTEST_FRAGMENT 1 // seed 003: fragment.z + bias < sceneZ
#define SSAO_FLAG_SEPARABLE 1
#define SSAO_FLAG_NOISE 2
#define SSAO_FLAG_POS_FROM_DEPTH 4
#define SSAO_FLAG_OFFSCREEN_CLAMP 8  // seeds: clamp-to-edge; else off-screen samples count as open
#define SSAO_FLAG_NORMAL_UNORM 16    // normals stored as (n+1)/2

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace ssao::gpu {
using mat4 = glm::mat4;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
#endif
#define SSAO_STRUCT struct

// std140. Matrices are column-major in both languages.
SSAO_STRUCT FrameConstants_ {
    mat4 view;        // world -> view (right-handed, camera looks down -z)
    mat4 proj;        // view -> clip (OpenGL, z_ndc in [-1,1])
    mat4 invProj;
    vec4 viewport;    // width, height, 1/width, 1/height  (pixels)
    vec4 clip;        // near, far, sceneRadius, unused    (scene units)
};

SSAO_STRUCT SsaoConstants_ {
    vec4 params0;     // radius (view units), bias (view units), power, rangeEpsilon
    vec4 noiseScale;  // xy: screen / 4 (noise tiles), zw: unused
    ivec4 modes;      // sampleCount, rangeCheck mode, depthTest mode, flags
    vec4 kernel[2 * SSAO_MAX_SAMPLES]; // [0,N): main set (or x-plane set), [256,256+N): y-plane set
};

SSAO_STRUCT BlurConstants_ {
    ivec4 taps;       // tapCount, direction (0 = x, 1 = y), unused, unused
    vec4 offsetsWeights[SSAO_MAX_BLUR_TAPS]; // x: offset in pixels, y: normalised weight
};

#ifdef __cplusplus
using FrameConstants = FrameConstants_;
using SsaoConstants = SsaoConstants_;
using BlurConstants = BlurConstants_;
static_assert(sizeof(FrameConstants) == 3 * 64 + 2 * 16, "std140 layout");
static_assert(sizeof(SsaoConstants) == 3 * 16 + 2 * SSAO_MAX_SAMPLES * 16, "std140 layout");
static_assert(sizeof(BlurConstants) == 16 + SSAO_MAX_BLUR_TAPS * 16, "std140 layout");
} // namespace ssao::gpu
#endif

#endif
