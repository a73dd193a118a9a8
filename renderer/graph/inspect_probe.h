// Runs a pass's shader for exactly one pixel with the INSPECT variant and reads back what the
// shader recorded (shaders/include/inspect.glsl): the sample inspector shows what the GPU did.
#pragma once
#include "gl/resources.h"
#include "graph/inspection.h"

#include <glm/glm.hpp>

#include <functional>

namespace ssao {

class InspectProbe {
  public:
    // Runs `draw` — which binds the pass's inputs and draws its INSPECT program — for pixel
    // (x, y from the top) of a `size` target only, through a framebuffer with no attachments, and
    // reads what the shader recorded into `out`. The scissor and framebuffer are restored even when
    // `draw` throws (e.g. the INSPECT variant fails to compile after a bad hot reload).
    void run(glm::ivec2 pixel, glm::ivec2 size, const std::function<void()>& draw, PixelInspection& out);

  private:
    gl::Buffer ssbo_;
    gl::Framebuffer fbo_;
    glm::ivec2 fboSize_{0};
};

} // namespace ssao
