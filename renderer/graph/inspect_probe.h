// Runs a pass's shader for exactly one pixel with the INSPECT variant and reads back what the
// shader recorded (shaders/include/inspect.glsl): the sample inspector shows what the GPU did.
#pragma once
#include "gl/handle.h"
#include "graph/inspection.h"

#include <glm/glm.hpp>

namespace ssao {

class InspectProbe {
  public:
    // Prepares the record for `pixel` (x, y from the top) of a `size` target and binds a
    // framebuffer with no attachments scissored to that pixel; then draw the INSPECT program.
    void begin(glm::ivec2 pixel, glm::ivec2 size);
    // Reads the record back into `out` (pixel, position, normal, taps, result).
    void end(PixelInspection& out);

  private:
    gl::BufferHandle ssbo_;
    gl::FramebufferHandle fbo_;
    glm::ivec2 fboSize_{0}, pixel_{0}, size_{0};
};

} // namespace ssao
