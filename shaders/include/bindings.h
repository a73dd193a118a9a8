// Binding points and GPU constant layouts shared by every pass, declared once for C++ and GLSL.
// C++ includes this file directly; the shader loader inlines it into GLSL via #include.
// A technique's own layout lives beside its shader (shaders/techniques/NAME.h).
#ifndef SSAOLAB_BINDINGS_H
#define SSAOLAB_BINDINGS_H

// ---- Texture units -------------------------------------------------------------------------
#define SSAO_TEX_POSITION 0     // gbuffer.position: view-space xyz + geometry mask (w = 1)
#define SSAO_TEX_NORMAL 1       // gbuffer.normal: view-space normal (raw or (n+1)/2 encoded)
#define SSAO_TEX_DEPTH 2        // gbuffer.zbuffer: hardware depth (window-space [0,1])
#define SSAO_TEX_ALBEDO 3       // gbuffer.albedo: base colour
#define SSAO_TEX_HISTORY 4      // temporal accumulation: the previous frame's AO, depth, count
#define SSAO_TEX_AO 5           // AO input of the denoise / composite passes
#define SSAO_TEX_LINEAR_DEPTH 6 // gbuffer.depth: linear view distance (positive), 0 = sky
#define SSAO_TEX_VIEW_SOURCE 7  // buffer shown by the view pass
#define SSAO_TEX_SCENE_ALPHA 7  // scene passes: a MASK draw's alpha texture (alpha_mask.glsl); the view pass binds its own
#define SSAO_TEX_VIEW_MASK 8    // geometry mask for the view pass (linear depth > 0)
#define SSAO_TEX_VIEW_SOURCE_B 9 // second buffer of a difference view
#define SSAO_TEX_TECHNIQUE 10   // first unit free for a technique's own textures
#define SSAO_TEX_BACK_DEPTH 12 // gbuffer.back_depth: linear depth of the nearest surface facing away
#define SSAO_TEX_POSITION_BAND 13 // gbuffer.guard_band: positions of the frame and a margin beyond it
#define SSAO_TEX_BLUE_NOISE 14  // 64x64 blue noise, two channels (techniques/noise/blue_noise.h)
#define SSAO_TEX_POSITION_MIPS 15 // gbuffer.position with a MIP pyramid (passes/position_pyramid_pass.h)
#define SSAO_TEX_SECOND_LAYER 16 // gbuffer.second_layer: the nearest front surface behind the first (passes/second_layer_pass.h)
#define SSAO_TEX_PREVIOUS_POSITION 17 // the G-buffer pass: the previous frame's gbuffer.position (second_layer_build = previous)

// ---- Image units -----------------------------------------------------------------------------
#define SSAO_IMG_SECOND_LAYER 0 // the G-buffer pass: gbuffer.second_layer as r32ui, atomic max of 1/depth's bits

// ---- Uniform / storage buffer bindings -----------------------------------------------------
#define SSAO_UBO_FRAME 0   // FrameConstants
#define SSAO_UBO_AO 1      // the AO technique's constants (first member: AoCommon)
#define SSAO_UBO_DENOISE 2 // DenoiseConstants
#define SSAO_UBO_USER 3    // a user technique's parameters (SsaoUserParams; renderer/techniques/user)
#define SSAO_SSBO_INSPECT 0 // sample inspector record (INSPECT builds only)
#define SSAO_LOC_AO_LAYER_CELL 30 // deinterleaved AO: the layer's cell of the 4x4 tile (noise.glsl, techniques/deinterleave.h)
#define SSAO_LOC_SECOND_LAYER_SEPARATION 31 // the second layer's minimum separation, scene units (passes/second_layer.frag)
#define SSAO_LOC_TO_PREVIOUS_VIEW 32 // mat4 (32-35): this frame's view space -> the previous frame's (passes/gbuffer.frag)
#define SSAO_LOC_PREVIOUS_PROJ 36    // mat4 (36-39): the previous frame's projection (passes/gbuffer.frag)

#define SSAO_MAX_DENOISE_TAPS 65 // 2*32+1 taps of a 1-D kernel
#define SSAO_BILATERAL_MAX_HALF_WIDTH 8 // the bilateral's 2-D window: at most 17x17
#define SSAO_DENOISE_NORMAL_UNORM 1     // bilateral: normals stored as (n+1)/2
#define SSAO_DENOISE_SKIP_SKY 2         // separable, last pass: sky pixels return 1 unfiltered
#define SSAO_INSPECT_MAX_TAPS 1024

// AoCommon.flags.w bits.
#define SSAO_AO_BAND 1
#define SSAO_AO_BACK_DEPTH 2
#define SSAO_AO_SECOND_LAYER 4

// Radius modes as the shaders see them (scene mode is resolved to world units on the CPU).
#define SSAO_RADIUS_WORLD 0
#define SSAO_RADIUS_SCREEN 1

// Per-pixel noise of the horizon techniques (AoCommon.estimator.y; techniques/noise/noise.h, same order).
#define SSAO_NOISE_IGN 0   // interleaved gradient noise (Jimenez 2014)
#define SSAO_NOISE_R2 1    // Roberts' R2 low-discrepancy sequence over the pixel grid (2018)
#define SSAO_NOISE_BLUE 2  // a 64x64 void-and-cluster blue-noise tile (Ulichney 1993)
#define SSAO_NOISE_TILE4 3 // a 4x4 tile of random values (the seeds' noise texture)
#define SSAO_NOISE_NONE 4

// Where the AO passes take normals from (AoCommon.estimator.z; settings.h NormalSource, same order).
#define SSAO_NORMALS_GBUFFER 0
#define SSAO_NORMALS_DEPTH 1 // reconstructed from positions, the smaller-difference neighbour per axis

// Tap states recorded by the inspector (graph/inspection.h: TapState, same order).
#define SSAO_TAP_OPEN 0
#define SSAO_TAP_OCCLUDED 1
#define SSAO_TAP_BEHIND_EYE 2
#define SSAO_TAP_OFFSCREEN 3
#define SSAO_TAP_SKY 4
// OR-ed into a tap's state: the layer it read beyond the G-buffer's front surface (the inspector
// shows which). BACK_LAYER: the back-face layer gave its solid's far side (gbuffer.back_faces).
#define SSAO_TAP_BACK_LAYER 16
// SECOND_LAYER: the surface the depth buffer hides behind the tap (gbuffer.second_layer) closed sectors.
#define SSAO_TAP_SECOND_LAYER 32

// View modes (display/view.frag), one per Display kind plus the difference of two buffers.
#define SSAO_VIEW_COLOR 0
#define SSAO_VIEW_SCALAR 1 // one channel, [lo, hi] → [0, 1], optional false colour
#define SSAO_VIEW_VECTOR 2 // xyz, each [lo, hi] → [0, 1]
#define SSAO_VIEW_DIFF 3   // (a - b) * scale, signed, diverging colours
#define SSAO_VIEW_SIGNED 4 // one signed channel, [-hi, hi]: blue < 0, white 0, red > 0 (error.png's map)

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
    mat4 view;     // world -> view (right-handed, camera looks down -z)
    mat4 proj;     // view -> clip (standard depth: z_ndc in [-1,1]; reversed: [0,1], 1 at near)
    mat4 invProj;
    vec4 viewport; // width, height, 1/width, 1/height of the G-buffer (pixels)
    vec4 clip;     // near, far, sceneRadius (scene units), temporal frame index (0 without temporal)
    vec4 camera;   // x: 1 = orthographic, y: 1 = reversed depth, z, w: unused
};

// What every AO technique shares (settings/settings.h AoSettings), first in its constant block.
SSAO_STRUCT AoCommon_ {
    vec4 radius; // x: world radius (world and scene modes), y: scene units per pixel at unit
                 // depth (screen mode: radius = y * depth * radiusPx), z: mode, w: radius in pixels
    vec4 estimator; // x: power, y: noise kind (SSAO_NOISE_*), z: normal source (SSAO_NORMALS_*),
                    // w: position-pyramid offset: taps d pixels away read MIP log2(d) - w (0 = no pyramid)
    vec4 target;    // AO target width, height, 1/width, 1/height (pixels)
    vec4 flags;     // x: 1 = sky pixels return at once (skip.sky), y: adaptive samples' pixels per
                    // sample (0 = off), z: 1 = normals stored as (n+1)/2 (an RGBA8 target), w: bits
                    // SSAO_AO_BAND (a guard band is bound: taps off the frame read it) and
                    // SSAO_AO_BACK_DEPTH (back-face depth is bound; position_taps.glsl)
};

SSAO_STRUCT DenoiseConstants_ {
    ivec4 taps;  // tapCount, direction (0 = x, 1 = y), unused, unused
    vec4 offsetsWeights[SSAO_MAX_DENOISE_TAPS]; // x: offset in input pixels, y: normalised weight
};

// std430 record of one pixel's taps (inspect.glsl).
SSAO_STRUCT InspectHeader_ {
    ivec4 pixelCount; // x, y: pixel (AO resolution, GL origin), z: taps recorded, w: 1 = geometry
    vec4 result;      // x: AO written, y: occlusion sum, z: normaliser, w: world radius used
    vec4 position;    // view-space position (xyz)
    vec4 normal;      // view-space normal (xyz)
};
SSAO_STRUCT InspectTap_ {
    vec4 posContribution; // xyz: sample point (view space), w: occlusion contributed
    vec4 uvStateSet;      // xy: uv it projects to, z: SSAO_TAP_*, w: set
};

#ifdef __cplusplus
using FrameConstants = FrameConstants_;
using AoCommon = AoCommon_;
using DenoiseConstants = DenoiseConstants_;
using InspectHeader = InspectHeader_;
using InspectTap = InspectTap_;
static_assert(sizeof(FrameConstants) == 3 * 64 + 3 * 16, "std140 layout");
static_assert(sizeof(AoCommon) == 4 * 16, "std140 layout");
static_assert(sizeof(DenoiseConstants) == 16 + SSAO_MAX_DENOISE_TAPS * 16, "std140 layout");
static_assert(sizeof(InspectHeader) == 4 * 16 && sizeof(InspectTap) == 2 * 16, "std430 layout");
} // namespace ssao::gpu
#endif

#endif
