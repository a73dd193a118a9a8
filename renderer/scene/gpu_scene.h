// The scene's triangles in GL buffers, drawn one draw call per material.
#pragma once
#include "gl/handle.h"
#include "scene/scene.h"

#include <vector>

namespace ssao {

class GpuScene {
  public:
    GpuScene() = default;
    explicit GpuScene(const Scene& scene);
    // Binds the VAO and issues every draw; `colorLocation` receives the base colour.
    void draw(GLint colorLocation) const;
    float radius() const { return radius_; }

  private:
    gl::VertexArrayHandle vao_;
    gl::BufferHandle vbo_, ibo_;
    std::vector<Draw> draws_;
    float radius_ = 1.0f;
};

} // namespace ssao
