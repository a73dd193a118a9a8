// The 36 corner indices of a box's 12 triangles, counter-clockwise seen from outside; corner c
// picks max x where bit 0 is set, max y for bit 1, max z for bit 2. Shared by C++
// (scene/gpu/occlusion_culler.h) and GLSL (passes/occlusion_box.vert), so the box the occlusion test
// draws faces the way its face culling assumes in both.
#ifndef SSAOLAB_BOX_CORNERS_H
#define SSAOLAB_BOX_CORNERS_H
#define SSAO_BOX_CORNERS 4, 6, 2, 4, 2, 0, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 6, 7, 3, 6, 3, 2, 2, 3, 1, 2, 1, 0, 4, 5, 7, 4, 7, 6
#endif
