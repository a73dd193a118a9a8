// Display versions (RGBA8) of every intermediate buffer, for the app's buffer grid. A view is
// re-rendered only when the pass that produced its source ran since the last update.
#pragma once
#include "renderer.h"

#include <array>
#include <string>

namespace ssao {

class BufferViews {
  public:
    // Brings every view up to date with the renderer's buffers.
    void update(Renderer& r);
    const gl::Texture2D& view(BufferId id) const;

  private:
    std::array<gl::RenderTarget, kBufferCount - 1> targets_; // composite is already displayable
    std::array<unsigned, kBufferCount> versions_{};
    const Renderer* owner_ = nullptr;
    const gl::Texture2D* composite_ = nullptr;
};

} // namespace ssao
