// The scene's triangles in GL buffers, drawn one draw call per material.
#pragma once
#include "gl/resources.h"
#include "scene/gpu/motion_lod.h"
#include "scene/scene.h"

#include <vector>

namespace ssao {

struct DrawStats {
    size_t draws = 0, culled = 0;         // draws issued, and skipped as outside the view
    size_t triangles = 0, trianglesCulled = 0;
    size_t trianglesFaceCulled = 0; // of `triangles`, drawn with face culling (closed shells)
    int lod = -1;                   // the level of the clustered mesh drawn (DrawOptions::lod), -1: the scene's
    size_t lodCoarser = 0;          // draws that took a level coarser than `lod` (DrawOptions::lodView)
    // DrawOptions::occlusion: draws left out as hidden (their boxes behind the depth drawn before
    // them), their triangles, and the boxes tested (of draws not visible in the last run; a box the
    // near plane reaches is not tested: its draw is drawn).
    size_t occluded = 0, trianglesOccluded = 0, boxesTested = 0;
};

class OcclusionCuller;

// How a pass draws the scene. `viewProj` is the pass's view; `zeroToOneDepth` its clip depth
// range ([0, w], 1 at near: reversed-Z).
struct DrawOptions {
    const glm::mat4* viewProj = nullptr;
    bool zeroToOneDepth = false;
    bool frustumCull = false; // skip draws whose bounds lie outside the view (skip.cull)
    // Cull the hidden side of closed shells (scene/closed_shells.h) wherever the shells' bounds lie
    // wholly beyond the near plane, which puts the eye outside them and keeps the near plane from
    // opening them (skip.hidden_faces). Only for passes that keep the nearest surface.
    bool hiddenFaces = false;
    // A level of the clustered copies (scene/gpu/motion_lod.h; -1: the scene itself): frames drawn while
    // the camera moves (skip.motion_lod). Its triangles are drawn without face culling. It is the
    // finest level drawn: with `lodView` set, each draw takes the coarsest level whose cell covers
    // at most a pixel of the frame at that draw's own nearest depth (motionLodCellPx), so a part
    // far from the camera is not drawn as finely as the nearest one needs (2CylinderEngine's moving
    // frame at its camera: 81 024 triangles instead of 89 190, 104 of its 115 draws coarser;
    // ReciprocatingSaw's heavy draws are its nearest: unchanged).
    int lod = -1;
    const glm::mat4* lodView = nullptr; // world -> view of the frame
    float lodProjY = 0.0f;              // the projection's proj[1][1]
    bool lodOrthographic = false;
    int lodHeight = 0; // pixels
    // skip.occluded: draws the culler's visible set first, then only those of the other draws whose
    // bounding box shows past that depth (scene/gpu/occlusion_culler.h; begin() called for this run).
    OcclusionCuller* occlusion = nullptr;
};

// True when the box cannot touch the view volume of `viewProj` (clip space: |x|, |y| <= w and
// z in [-w, w], or [0, w] with reversed depth): all 8 corners outside one plane. Conservative -
// a box that straddles corners of the frustum may be kept - never wrong the other way.
bool outsideFrustum(const Bounds& box, const glm::mat4& viewProj, bool zeroToOneDepth);

// True when every corner of the box lies strictly on the far side of the near plane of `viewProj`:
// then the eye is outside the box and the near plane cuts nothing in it.
bool beyondNearPlane(const Bounds& box, const glm::mat4& viewProj, bool zeroToOneDepth);

// The programs a pass draws the scene with: `opaque` for every draw without a cut-out, `mask`
// (the same shaders built with ALPHA_MASK: include/alpha_mask.glsl) for MASK draws, which get
// their alpha test at the uniform locations and texture unit alpha_mask.glsl declares. The mask
// variant is separate because a shader that may discard loses the early depth test.
struct ScenePrograms {
    GLuint opaque = 0, mask = 0;
    GLint colorLocation = -1; // receives the base colour (-1: none), in both programs
};

class GpuScene {
  public:
    GpuScene() = default;
    // motionLods: also build the clustered copies (scene/gpu/motion_lod.h) where the scene is large
    // enough; only the app draws them (while the camera moves), so headless renders skip the work.
    explicit GpuScene(const Scene& scene, bool motionLods = false);
    // Binds the VAO and issues the draws, MASK draws last, as `o` asks. Leaves face culling off.
    DrawStats draw(const ScenePrograms& programs, const DrawOptions& o = {}) const;
    size_t drawCount() const { return draws_.size(); }
    float radius() const { return radius_; }
    bool hasMask() const { return hasMask_; } // a MASK draw: callers build ScenePrograms::mask
    // The clustered copies, coarsest first: each one's cell edge (scene units) and triangle count.
    int lodLevels() const { return int(lods_.size()); }
    float lodCell(int level) const { return lods_[size_t(level)].cell; }
    size_t lodTriangles(int level) const { return lods_[size_t(level)].triangles; }
    const Bounds& bounds() const { return bounds_; }
    // Pixels of a frame `height` tall that one cell of `level` may cover: the most over the draws'
    // own bounds (motionLodCellPx; tighter than the scene's box, whose corners are empty space).
    float lodCellPx(int level, const Camera& camera, int height) const;

  private:
    gl::VertexArray vao_;
    gl::Buffer vbo_, ibo_, uvs_;
    struct LodLevel { // one clustered copy: the same vertices, its own indices
        float cell = 0.0f;
        size_t triangles = 0;
        gl::Buffer ibo;
        gl::VertexArray vao;
        std::vector<uint32_t> first, count; // per draw, in indices
    };
    std::vector<LodLevel> lods_;
    std::vector<gl::Texture2D> alpha_; // per Scene::alphaTextures, R8
    std::vector<glm::ivec2> alphaWrap_;
    bool hasMask_ = false;
    // A draw's triangles in the index buffer: the closed shells' Outward ones, then Inward, then
    // the rest (the scene's order within each group), with the bounds of each group.
    struct GpuDraw {
        Draw draw;
        Bounds bounds;
        uint32_t outward = 0, inward = 0; // triangles
        Bounds outwardBounds, inwardBounds;
    };
    std::vector<GpuDraw> draws_;
    float radius_ = 1.0f;
    Bounds bounds_;
    void bindAttributes(GLuint vao) const;
    // The clustered level draw `di` takes under `o` (null: the scene's own triangles).
    const LodLevel* levelFor(size_t di, const DrawOptions& o) const;
    // Draw `di` (its uniforms, its LOD level or its face-culled groups); the program is bound.
    void drawOne(size_t di, const ScenePrograms& programs, const DrawOptions& o, GLuint& boundVao,
                 DrawStats& st) const;
};

} // namespace ssao
