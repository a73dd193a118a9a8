// Closed shells: the triangles whose back faces can never be the nearest surface.
//
// A closed, consistently wound surface (every edge shared by exactly two of its triangles, which
// run along it in opposite directions) bounds a solid. A ray from a point outside that solid
// crosses one of its front faces before any of its back faces, whatever else the scene holds, so
// while the eye and the near plane are outside the solid the depth test would discard every one of
// its back faces: the G-buffer may cull them (GL_CULL_FACE) and see exactly the same surfaces.
// Which faces are "back" follows from the shell's signed volume: positive (outward normals by the
// right-hand rule of the counter-clockwise order, OpenGL's front faces) culls GL_BACK, negative (an
// inside-out shell) GL_FRONT. CAD exports often mix both, and meshes that are open, non-manifold,
// T-junctioned or of (near) zero volume get no culling at all: the analysis only ever says "cull"
// where the result is exact.
#pragma once
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ssao {

enum class ShellFacing : int8_t {
    Open = 0,     // not on a closed shell found here: drawn with no culling
    Outward = 1,  // on a closed shell of positive volume: its GL back faces are hidden
    Inward = -1,  // on a closed shell of negative volume: its GL front faces are hidden
};

// The largest triangle count one call analyses: ~130 bytes of scratch per triangle, and its time
// grows with the count, so it bounds a load's memory and pause. A range beyond it is reported all
// Open (drawn as before, with no culling).
constexpr size_t kShellMaxTriangles = size_t(1) << 20;

// The weld table's hash of a position's bits (-0 as +0): MurmurHash3's finaliser mixes every bit
// into the low ones, which round coordinates (a grid of instances) leave zero in a plain product.
uint64_t weldHash(const glm::vec3& p);

// One ShellFacing per triangle of indices[first, first + 3 * triangles). Vertices are welded by
// exact position (split normals and UV seams do not open a shell); a triangle that collapses
// under welding covers no pixel and is Open. Shells are found within the range only: a solid split
// across two ranges (two materials) is Open in both.
std::vector<ShellFacing> classifyShells(const std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices,
                                        size_t first, size_t triangles);

} // namespace ssao
