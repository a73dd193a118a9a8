// Final image: ambient * albedo * AO + one point light (seed 004), display gamma, RGBA8.
#pragma once
#include "passes/blur_pass.h"

#include <memory>

namespace ssao {

class CompositePass final : public Pass {
  public:
    CompositePass(const GBufferPass& g, const BlurPass& b) : gbuffer_(g), blur_(b) {}
    const char* name() const override { return "composite"; }
    std::vector<std::string> settingGroups() const override { return {"composite"}; }
    std::vector<const Pass*> inputs() const override { return {&gbuffer_, &blur_}; }
    void run(const FrameInputs& in) override;

    const gl::Texture2D& color() const { return color_; }

  private:
    const GBufferPass& gbuffer_;
    const BlurPass& blur_;
    gl::Texture2D color_;
    std::unique_ptr<gl::Framebuffer> fbo_;
};

} // namespace ssao
