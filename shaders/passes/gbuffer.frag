#version 450 core
// G-buffer in view space (seeds 000/003/004): position, normal, albedo, linear depth.
#include "include/frame.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;

layout(location = 0) uniform vec4 uBaseColor;

layout(location = 0) out vec4 oPosition;    // xyz view position, w = 1 marks geometry (sky = 0)
layout(location = 1) out vec4 oNormal;      // view normal, or (n+1)/2 when NORMAL_UNORM
layout(location = 2) out vec4 oAlbedo;
layout(location = 3) out float oLinearDepth; // distance along -z, scene units (sky = 0)

void main() {
    // Geometric normal of the visible face, oriented towards the viewer.
    vec3 gn = cross(dFdx(vViewPos), dFdy(vViewPos));
    float gl2 = dot(gn, gn);
    gn = gl2 > 0.0 ? gn * inversesqrt(gl2) : vec3(0.0, 0.0, 1.0);
    if (dot(gn, -vViewPos) < 0.0) gn = -gn;

    // Interpolated normals are shorter than 1: renormalise (guarding zero-length input).
    float nl2 = dot(vViewNormal, vViewNormal);
    vec3 n = nl2 > 1e-20 ? vViewNormal * inversesqrt(nl2) : gn;
    // Back faces of double-sided / inconsistently wound meshes: shade the side we see.
    if (dot(n, gn) < 0.0) n = -n;

    oPosition = vec4(vViewPos, 1.0);
#ifdef NORMAL_UNORM
    oNormal = vec4(n * 0.5 + 0.5, 1.0);
#else
    oNormal = vec4(n, 1.0);
#endif
    oAlbedo = uBaseColor;
    oLinearDepth = -vViewPos.z;
}
