// Occlusion culling of whole draws in the G-buffer (skip.occluded): what the scene hides is not
// drawn. Two phases a frame, in the manner of coherent hierarchical culling (Bittner, Wimmer,
// Piringer & Purgathofer 2004) at the granularity of draws, with hardware occlusion queries:
//  1. the draws that were visible in the last run are drawn, each inside an any-samples query
//     (did any of its fragments pass the depth test when it was drawn: next run's visible set);
//  2. every other draw's bounding box (grown by a rounding margin) is tested against the depth
//     they left, without writing anything, and only the draws whose box shows a sample are drawn.
// Exact: a draw left out has its whole box behind depth that the final image keeps (depth only
// ever comes nearer), so none of its fragments could have passed the depth test. The visible set
// only decides how much is drawn before the test: a wrong guess costs time, never pixels. A box
// the near plane reaches is not tested (its draw is drawn). Ties between coplanar surfaces of two
// draws may resolve the other way when a draw of phase 2 comes after one it preceded, and the
// margin is in scene units: where the depth buffer cannot tell two surfaces apart (z-fighting) a
// test at the same depth may go either way.
//
// Why: on llvmpipe the G-buffer of a CAD assembly is bound by its triangles (set up on one
// thread before any pixel), and most of an assembly's parts are inside others: at their own
// cameras 104 of 2CylinderEngine's 115 draws (71 475 of 121 496 triangles) and 66 of
// ReciprocatingSaw's 113 (85 075 of 198 470) leave no pixel (counted with a query per draw).
#pragma once
#include "gl/handle.h"
#include "gl/resources.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ssao {

class OcclusionCuller {
  public:
    // Starts a run over `draws` draws; `scene` identifies what they are (another scene, or a
    // changed draw count, forgets the visible set: every draw is then drawn in phase 1).
    // `boxProgram` draws a box (shaders/passes/occlusion_box.vert): its corners at uniform
    // locations 1 (vec3 min) and 2 (vec3 max), transformed by the frame block as the scene is.
    void begin(size_t draws, unsigned scene, GLuint boxProgram);
    // Phase 1 or 2: whether the draw waits for its box test.
    bool deferred(size_t draw) const { return draw < visible_.size() && !visible_[draw]; }
    // Around a draw's calls: its query, read at the next begin().
    void beginDraw(size_t draw);
    void endDraw();
    // Phase 2: each box's visibility against the depth drawn so far, in the order given. Writes
    // nothing; leaves the G-buffer's state (SceneDrawState: depth and colour writes on, face culling
    // off) and no program bound. Blocks until the queries are answered (the draws so far
    // rasterised): on a GPU a stall per frame, on llvmpipe the wait its next pass makes anyway.
    // `viewProj` decides which boxes the near plane reaches; the boxes are drawn with the frame block.
    std::vector<bool> testBoxes(const std::vector<Bounds>& boxes, const glm::mat4& viewProj, bool zeroToOneDepth);
    // Boxes the last testBoxes() drew (those the near plane reaches are shown untested).
    size_t tested() const { return tested_; }

    // The box a test draws: `b` grown on every side by a margin over rounding (1e-4 of its
    // diagonal plus 1e-5 of its largest coordinate), so a surface lying on a face of its own
    // bounds is never in front of the box that stands for it.
    static Bounds grown(const Bounds& b);
    // The 36 corner indices (bit 0: max x, bit 1: max y, bit 2: max z) of the box's 12
    // triangles, counter-clockwise seen from outside (shaders/include/box_corners.h, which
    // occlusion_box.vert reads too).
    static const int kBoxCorners[36];

  private:
    std::vector<uint8_t> visible_;          // per draw: drawn in phase 1
    std::vector<gl::QueryHandle> queries_;  // per draw: any samples passed while it was drawn
    std::vector<uint8_t> pending_;          // per draw: its query was issued and is unread
    std::vector<gl::QueryHandle> boxQueries_;
    gl::VertexArray emptyVao_;
    unsigned scene_ = 0;
    GLuint boxProgram_ = 0;
    size_t current_ = 0, tested_ = 0;
    bool queried_ = false; // the draw between beginDraw and endDraw has a query running
};

} // namespace ssao
