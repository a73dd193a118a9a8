// Separable blur of the raw AO: x pass into a temporary, y pass into the output (float targets).
#pragma once
#include "passes/ssao_pass.h"

namespace ssao {

class BlurPass final : public Pass {
  public:
    explicit BlurPass(const SsaoPass& ssao) : ssao_(ssao) {}
    const char* name() const override { return "blur"; }
    std::vector<std::string> settingGroups() const override { return {"blur"}; }
    std::vector<const Pass*> inputs() const override { return {&ssao_}; }
    void run(const FrameInputs& in) override;

    const gl::Texture2D& ao() const { return out_.texture(); }

  private:
    const SsaoPass& ssao_;
    gl::RenderTarget tmp_, out_;
    gl::UniformBuffer ubo_[2];
};

} // namespace ssao
