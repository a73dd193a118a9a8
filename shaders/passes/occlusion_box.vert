#version 450 core
// A draw's bounding box for the G-buffer's occlusion test (renderer/scene/gpu/occlusion_culler.h):
// 12 triangles from gl_VertexID, counter-clockwise seen from outside (include/box_corners.h).
// Transformed as gbuffer.vert transforms the scene (proj * (view * p), the frame block), so the
// box and the meshes it stands for round alike.
#include "include/frame.glsl"
#include "include/box_corners.h"

layout(location = 1) uniform vec3 uMin; // world space, grown by OcclusionCuller::grown
layout(location = 2) uniform vec3 uMax;

const int kCorners[36] = int[36](SSAO_BOX_CORNERS);

void main() {
    int c = kCorners[gl_VertexID];
    vec3 t = vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
    gl_Position = frame.proj * (frame.view * vec4(mix(uMin, uMax, t), 1.0));
}
