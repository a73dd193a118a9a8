// A MIP pyramid of the G-buffer's view-space positions for techniques whose taps reach far (SAO,
// HBAO, GTAO, visibility bitmask with *.pyramid on): a tap d pixels from the pixel reads level
// log2(d) - offset, so wide radii touch few cache lines (McGuire 2012 §3.2; XeGTAO's depth
// prefilter plays this role). Level i+1 keeps one texel of each 2x2 block of level i, on SAO's
// rotated grid (2x + ((y & 1) ^ 1), 2y + ((x & 1) ^ 1)): every stored position is a real surface
// point (an average would float between a silhouette's two sides) and the mask in w stays exact.
// A pass of its own (timer, label, demand culling), shared by both chains: the renderer adds it
// when a chain's technique asks for the pyramid (TechniqueInfo::pyramid).
#pragma once
#include "graph/gbuffer_layers.h"
#include "graph/pass.h"
#include "settings/settings.h"

#include <vector>

namespace ssao {

class PositionPyramidPass final : public ConfiguredPass<NoConfig> {
  public:
    static constexpr int kMaxLevels = 6; // levels 0..5, like XeGTAO's 5 MIPs below the full size
    static constexpr const char* kOutput = gbuffer::kPositionMips;
    PositionPyramidPass() : ConfiguredPass("position_mips", Chain::a()) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    NoConfig config(const Settings&, const FrameInfo&) const override { return {}; } // its input alone

  private:
    void run(PassContext& ctx, const NoConfig& c) override;
    std::vector<gl::Framebuffer> levels_; // one per level >= 1 of the current texture
    unsigned textureId_ = 0;
};

} // namespace ssao
