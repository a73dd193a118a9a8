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

class GpuScene {
  public:
    GpuScene() = default;
    explicit GpuScene(const Scene& scene);
    // Binds the VAO and issues the draws; `colorLocation` receives the base colour. With
    // `cullViewProj`, draws whose bounds lie outside that view are skipped.
    DrawStats draw(GLint colorLocation, const glm::mat4* cullViewProj = nullptr, bool zeroToOneDepth = false) const;
    float radius() const { return radius_; }

  private:
    gl::VertexArray vao_;
    gl::Buffer vbo_, ibo_;
    std::vector<Draw> draws_;
    std::vector<Bounds> drawBounds_; // per draw, scene frame
    float radius_ = 1.0f;
};

} // namespace ssao
