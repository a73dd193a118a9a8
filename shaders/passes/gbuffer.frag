#version 450 core
// G-buffer in view space (seeds 000/003/004): position, normal, albedo, linear depth.
#include "include/frame.glsl"
#include "include/alpha_mask.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;

layout(location = 0) uniform vec4 uBaseColor;

// Each target is written only when its WRITE_* define gives it an attachment (the pass leaves
// out targets nothing reads this frame: skip.unused_targets).
#ifdef WRITE_POSITION
layout(location = WRITE_POSITION) out vec4 oPosition; // xyz view position, w = 1 marks geometry (sky = 0)
#endif
#ifdef WRITE_NORMAL
layout(location = WRITE_NORMAL) out vec4 oNormal; // view normal, or (n+1)/2 when NORMAL_UNORM
#endif
#ifdef WRITE_ALBEDO
layout(location = WRITE_ALBEDO) out vec4 oAlbedo;
#endif
#ifdef WRITE_DEPTH
layout(location = WRITE_DEPTH) out float oLinearDepth; // distance along -z, scene units (sky = 0)
#endif

#ifdef SECOND_LAYER_PREVIOUS
// The second depth layer in this same pass (gbuffer.second_layer_build = previous; Mara, McGuire,
// Nowrouzezahrai and Luebke, HPG 2016, the single pass with the previous frame's depth): a fragment
// facing the eye that lies more than the separation behind the previous frame's first layer, where
// it was then, competes for the nearest through an atomic max of 1/depth (positive floats order as
// their bits). The image store keeps the depth test after the shader, so hidden fragments run too.
layout(binding = SSAO_TEX_PREVIOUS_POSITION) uniform sampler2D gPrevious; // the previous frame's gbuffer.position
layout(binding = SSAO_IMG_SECOND_LAYER, r32ui) uniform coherent uimage2D gSecondLayer;
layout(location = SSAO_LOC_TO_PREVIOUS_VIEW) uniform mat4 uToPrevious; // this view -> the previous one
layout(location = SSAO_LOC_PREVIOUS_PROJ) uniform mat4 uPreviousProj;
layout(location = SSAO_LOC_SECOND_LAYER_SEPARATION) uniform float uSeparation; // scene units; inf: no history

void keepSecondLayer() {
    if (dot(vViewNormal, frameViewVector(vViewPos)) < 0.0) return; // faces away: the back-face layer's
    vec4 p = uToPrevious * vec4(vViewPos, 1.0);
    vec4 clip = uPreviousProj * p;
    if (clip.w <= 0.0) return;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return; // unseen then
    vec4 first = texelFetch(gPrevious, ivec2(uv * vec2(textureSize(gPrevious, 0))), 0);
    if (first.w == 0.0 || !(-p.z > -first.z + uSeparation)) return; // the first layer, or too near it
    imageAtomicMax(gSecondLayer, ivec2(gl_FragCoord.xy), floatBitsToUint(1.0 / -vViewPos.z));
}
#endif

void main() {
    alphaMaskTest(vUv); // MASK draws: cut-outs are not surfaces
#ifdef SECOND_LAYER_PREVIOUS
    keepSecondLayer();
#endif
#ifdef WRITE_POSITION
    oPosition = vec4(vViewPos, 1.0);
#endif
#ifdef WRITE_ALBEDO
    oAlbedo = uBaseColor;
#endif
#ifdef WRITE_DEPTH
    oLinearDepth = -vViewPos.z;
#endif
#ifdef WRITE_NORMAL
    // Geometric normal of the visible face, oriented towards the viewer.
    vec3 gn = cross(dFdx(vViewPos), dFdy(vViewPos));
    float gl2 = dot(gn, gn);
    gn = gl2 > 0.0 ? gn * inversesqrt(gl2) : vec3(0.0, 0.0, 1.0);
    if (dot(gn, frameViewVector(vViewPos)) < 0.0) gn = -gn;

    // Interpolated normals are shorter than 1: renormalise (guarding zero-length input).
    float nl2 = dot(vViewNormal, vViewNormal);
    vec3 n = nl2 > 1e-20 ? vViewNormal * inversesqrt(nl2) : gn;
    // Back faces of double-sided / inconsistently wound meshes: shade the side we see.
    if (dot(n, gn) < 0.0) n = -n;

#ifdef NORMAL_UNORM
    oNormal = vec4(n * 0.5 + 0.5, 1.0);
#else
    oNormal = vec4(n, 1.0);
#endif
#endif
}
