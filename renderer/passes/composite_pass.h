// Final image: ambient * albedo * AO + one point light (seed 004), display gamma, RGBA8.
#pragma once
#include "passes/blur_pass.h"

namespace ssao {

class CompositePass final : public Pass {
  public:
    CompositePass(const GBufferPass& g, const BlurPass& b) : gbuffer_(g), blur_(b) {}
    const char* name() const override { return "composite"; }
    std::vector<std::string> settingGroups() const override { return {"composite"}; }
    std::vector<const Pass*> inputs() const override { return {&gbuffer_, &blur_}; }
    void run(const FrameInputs& in) override;

    const gl::Texture2D& color() const { return target_.texture(); }

  private:
    const GBufferPass& gbuffer_;
    const BlurPass& blur_;
    gl::RenderTarget target_;
};

} // namespace ssao
