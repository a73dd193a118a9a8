#version 450 core
// A draw's bounding box for the G-buffer's occlusion test (renderer/scene/occlusion_culler.h):
// 12 triangles from gl_VertexID, counter-clockwise seen from outside.
layout(location = 0) uniform mat4 uViewProj; // world -> clip, as the G-buffer draws
layout(location = 1) uniform vec3 uMin;      // world space, grown by OcclusionCuller::grown
layout(location = 2) uniform vec3 uMax;

// OcclusionCuller::kBoxCorners: bit 0 picks max x, bit 1 max y, bit 2 max z.
const int kCorners[36] = int[36](4, 6, 2, 4, 2, 0, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                 6, 7, 3, 6, 3, 2, 2, 3, 1, 2, 1, 0, 4, 5, 7, 4, 7, 6);

void main() {
    int c = kCorners[gl_VertexID];
    vec3 t = vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
    gl_Position = uViewProj * vec4(mix(uMin, uMax, t), 1.0);
}
