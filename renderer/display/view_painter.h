// Paints a buffer of the frame graph into a displayable RGBA8 image with the mapping of
// display_range.h (shaders/display/view.frag). The app's views and the PNG previews both come
// from here, so they can never disagree.
#pragma once
#include "display/display_range.h"
#include "display/fit_samples.h"
#include "gl/resources.h"
#include "graph/resource.h"

namespace ssao {

namespace gl {
class ShaderLibrary;
}

class ViewPainter {
  public:
    // Paints `r` into `out`, resized to r's size or, with maxWidth > 0, to at most that many
    // pixels wide at r's aspect (a grid cell: each output pixel takes the texel at its centre, so a
    // thumbnail costs its own pixels, not the buffer's); `mask` marks geometry (gbuffer.depth > 0).
    // When its range must be fitted, uses `keep` if given (no read-back), else `raw` (r read back,
    // undecoded), else reads back the texels a fit reads (display/fit_samples.h). Returns the range used.
    DisplayRange paint(const Resource& r, const Resource& mask, const ViewStyle& style, gl::RenderTarget& out,
                       gl::ShaderLibrary& shaders, const gl::FullscreenTriangle& tri,
                       const Image* raw = nullptr, int maxWidth = 0, const DisplayRange* keep = nullptr);
    // Signed difference (a - b) * scale of two same-kind buffers, red where a is larger, blue where
    // b is, grey where equal.
    void paintDifference(const Resource& a, const Resource& b, float scale, const Resource& mask,
                         gl::RenderTarget& out, gl::ShaderLibrary& shaders,
                         const gl::FullscreenTriangle& tri);

  private:
    const Image& maskImage(const Resource& mask);
    FitSamplePicker picker_;
    Image mask_;
    uint64_t maskVersion_ = 0;
    unsigned maskGeneration_ = 0;
};

} // namespace ssao
