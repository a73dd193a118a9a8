// Kernel SSAO (shaders/passes/ssao.frag) into a float target: R32F, never 8-bit, because an
// 8-bit target turns a NaN into 1.0 on llvmpipe and hides the bug from every test.
#pragma once
#include "passes/gbuffer_pass.h"

namespace ssao {

class SsaoPass final : public Pass {
  public:
    explicit SsaoPass(const GBufferPass& gbuffer) : gbuffer_(gbuffer) {}
    const char* name() const override { return "ssao"; }
    std::vector<std::string> settingGroups() const override { return {"ssao"}; }
    std::vector<const Pass*> inputs() const override { return {&gbuffer_}; }
    void run(const FrameInputs& in) override;

    const gl::Texture2D& aoRaw() const { return target_.texture(); }

  private:
    const GBufferPass& gbuffer_;
    gl::RenderTarget target_;
    gl::Texture2D noise_;
    gl::UniformBuffer ubo_;
    int noiseSeed_ = -1;
};

} // namespace ssao
