// Separable blur of the raw AO: x pass into a temporary, y pass into the output (float targets).
#pragma once
#include "passes/ssao_pass.h"

#include <memory>

namespace ssao {

class BlurPass final : public Pass {
  public:
    explicit BlurPass(const SsaoPass& ssao) : ssao_(ssao) {}
    const char* name() const override { return "blur"; }
    std::vector<std::string> settingGroups() const override { return {"blur"}; }
    std::vector<const Pass*> inputs() const override { return {&ssao_}; }
    void run(const FrameInputs& in) override;

    const gl::Texture2D& ao() const { return out_; }

  private:
    const SsaoPass& ssao_;
    gl::Texture2D tmp_, out_;
    std::unique_ptr<gl::Framebuffer> fboTmp_, fboOut_;
    gl::UniformBuffer ubo_[2];
};

} // namespace ssao
