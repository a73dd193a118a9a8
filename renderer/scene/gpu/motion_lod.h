// The mesh the G-buffer draws while the camera moves (skip.motion_lod): the scene's triangles with
// their vertices clustered on a grid of cells, so that triangles smaller than a cell disappear.
//
// Why: on llvmpipe a triangle's setup and binning run on one thread whatever the resolution, so
// a CAD model's G-buffer does not shrink with the frame drawn while moving (the drag frames of
// docs/bench/explorer.md). Frames drawn while moving are at a reduced resolution; where one cell
// projects to at most a pixel of that frame (motionLodCellPx), the clustered mesh covers the same
// pixels but for sub-pixel slivers, and the still frame that follows draws the full mesh again.
//
// Vertex clustering (Rossignac & Borrel 1993): each vertex is replaced by the first vertex of its
// draw that fell in the same cell, so every position drawn is one of the scene's own (no new
// vertex buffer, normals and texture coordinates kept); a triangle whose corners fall in fewer
// than three cells is dropped, and so is a second copy of the same three. Vertices whose normals
// lie in different ones of 24 cones (octant and largest axis) never merge: the two sides of a wall
// thinner than a cell stay two sides, and a hard edge keeps each face's normal (with octants
// alone the saw's moving AO moved by 0.025 on average, with the cones 0.005; tests/gl). Draws are clustered separately (materials never mix); MASK draws are kept whole (their
// cut-outs follow texture coordinates).
#pragma once
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ssao {

// Below this many triangles a scene's G-buffer costs little while moving: no clustered copy.
constexpr size_t kMotionLodMinTriangles = 40000;
// The levels' cells per bounding-box diagonal, coarsest first: each shrinks the last one's cell by
// sqrt 2, so the coarsest level whose cell covers at most a pixel has cells of 0.71 to 1 pixel.
constexpr float kMotionLodCellsPerDiagonal[] = {96.0f, 135.76f, 192.0f, 271.53f, 384.0f, 543.06f, 768.0f};

struct MotionLod {
    float cell = 0.0f;                  // edge of a cell, scene units (0: no copy built)
    std::vector<uint32_t> indices;      // every draw's kept triangles, in the scene's draw order
    std::vector<uint32_t> first, count; // per Scene::draws entry: its range of `indices` (count a multiple of 3)
    size_t triangles() const { return indices.size() / 3; }
};

// The clustered copy with cells of edge `cell` (> 0, scene units); positions relative to
// scene.bounds.min (cells past 2^19 on an axis share the last one).
MotionLod buildMotionLod(const Scene& scene, float cell);

// The copies a scene gets, coarsest first: none below kMotionLodMinTriangles triangles, and only the
// levels that keep at most 75 % of the triangles (a finer one would save too little to be worth
// its index buffer; the ones after it would keep still more).
std::vector<MotionLod> motionLodsFor(const Scene& scene);

// How many pixels of a frame `height` pixels tall one cell of edge `cell` can cover at most: the
// cell at the least depth any point of `bounds` has along the view axis (perspective), or at the
// view's scale (orthographic). Infinite when the bounds reach the eye's plane, 0 when they lie
// wholly behind it (nothing of them is seen).
float motionLodCellPx(float cell, const Bounds& bounds, const Camera& camera, int height);
// The same for a frame given as the G-buffer's constants hold it (graph/pass_config.h): `view`
// world -> view (a rigid lookAt), `projY` the projection's y scale (proj[1][1]: 1 / tan(fov/2),
// or 1 / the half height when orthographic).
float motionLodCellPx(float cell, const Bounds& bounds, const glm::mat4& view, float projY, bool orthographic,
                      int height);

} // namespace ssao
