// Final image: ambient * albedo * AO + one point light (seed 004), display gamma, RGBA8.
#pragma once
#include "graph/pass.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct CompositeConfig {
    gpu::FrameConstants frame; // the light's placement in scene radii (without the frame index)
    float ambient, light;
    int32_t useAo;       // reads the chain's ao.denoised
    int32_t normalUnorm; // normals stored as (n+1)/2
};
SSAO_CONFIG_END

class CompositePass final : public ConfiguredPass<CompositeConfig> {
  public:
    explicit CompositePass(const Chain& c) : ConfiguredPass(c.res("composite"), c) {}
    void setup(PassBuilder& b, const Settings& s) const override;
    CompositeConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    void run(PassContext& ctx, const CompositeConfig& c) override;
};

} // namespace ssao
