// The scene's triangles in GL buffers, drawn one draw call per material.
#pragma once
#include "gl/resources.h"
#include "scene/scene.h"

#include <vector>

namespace ssao {

struct DrawStats {
    size_t draws = 0, culled = 0;         // draw calls issued, and skipped as outside the view
    size_t triangles = 0, trianglesCulled = 0;
};

// True when the box cannot touch the view volume of `viewProj` (clip space: |x|, |y| <= w and
// z in [-w, w], or [0, w] with reversed depth): all 8 corners outside one plane. Conservative -
// a box that straddles corners of the frustum may be kept - never wrong the other way.
bool outsideFrustum(const Bounds& box, const glm::mat4& viewProj, bool zeroToOneDepth);

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
    explicit GpuScene(const Scene& scene);
    // Binds the VAO and issues the draws, MASK draws last. With `cullViewProj`, draws whose bounds
    // lie outside that view are skipped.
    DrawStats draw(const ScenePrograms& programs, const glm::mat4* cullViewProj = nullptr, bool zeroToOneDepth = false) const;
    float radius() const { return radius_; }
    bool hasMask() const { return hasMask_; } // a MASK draw: callers build ScenePrograms::mask

  private:
    gl::VertexArray vao_;
    gl::Buffer vbo_, ibo_, uvs_;
    std::vector<gl::Texture2D> alpha_; // per Scene::alphaTextures, R8
    std::vector<glm::ivec2> alphaWrap_;
    bool hasMask_ = false;
    std::vector<Draw> draws_;
    std::vector<Bounds> drawBounds_; // per draw, scene frame
    float radius_ = 1.0f;
};

} // namespace ssao
