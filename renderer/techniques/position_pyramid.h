// A MIP pyramid of the G-buffer's view-space positions for techniques whose taps reach far
// (SAO, GTAO, visibility bitmask): a tap d pixels from the pixel reads level log2(d) - offset, so
// wide radii touch few cache lines (McGuire 2012 §3.2; XeGTAO's depth prefilter plays this role).
// Level i+1 keeps one texel of each 2x2 block of level i, on SAO's rotated grid
// (2x + ((y & 1) ^ 1), 2y + ((x & 1) ^ 1)): every stored position is a real surface point (an
// average would float between a silhouette's two sides) and the mask in w stays exact.
#pragma once
#include "gl/handle.h"
#include "gl/resources.h"

#include <vector>

namespace ssao {

class PassContext;

class PositionPyramid {
  public:
    static constexpr int kMaxLevels = 6; // levels 0..5, like XeGTAO's 5 MIPs below the full size
    // Rebuilds every level from `positions` (the same size and format are kept while they match).
    void build(PassContext& ctx, const gl::Texture2D& positions);
    void bind(GLuint unit) const { glBindTextureUnit(unit, tex_.id()); }
    int levels() const { return levels_; }

  private:
    gl::TextureHandle tex_;
    std::vector<gl::FramebufferHandle> fbos_; // one per level >= 1
    int w_ = 0, h_ = 0, levels_ = 0;
    GLenum fmt_ = 0;
};

} // namespace ssao
