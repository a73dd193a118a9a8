// The samples of a display-range fit (display_range.h fitSamples) picked on the GPU: one small
// pass writes the ~65k texels the fit reads, and only those come back. The same texels as a fit of
// the whole read-back buffer, so the app's views and the PNG previews keep the same ranges.
#pragma once
#include "display/display_range.h"
#include "gl/resources.h"

namespace ssao {

namespace gl {
class ShaderLibrary;
}

class FitSamplePicker {
  public:
    // fitSamples(readBack(src), &readBack(mask)), read back as kWidth-wide rows of RGBA32F.
    std::vector<FitSample> pick(const gl::Texture2D& src, const gl::Texture2D& mask, gl::ShaderLibrary& shaders,
                                const gl::FullscreenTriangle& tri);
    static constexpr int kWidth = 256;

  private:
    gl::RenderTarget target_;
};

} // namespace ssao
