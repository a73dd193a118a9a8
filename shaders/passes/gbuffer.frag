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

void main() {
    alphaMaskTest(vUv); // MASK draws: cut-outs are not surfaces
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
