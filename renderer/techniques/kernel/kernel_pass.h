// Kernel SSAO's pass: reads the G-buffer (positions or the depth buffer, normals), writes ao.raw
// (techniques/ao_pass.h).
#pragma once
#include "techniques/ao_pass.h"

namespace ssao {

class KernelPass final : public AoPass {
  public:
    using AoPass::AoPass;
    void setup(PassBuilder& b, const Settings& s) const override;

  private:
    std::string prepare(PassContext& ctx) override;
    gl::Texture2D noise_;
    gl::UniformBuffer ubo_;
    int noiseSeed_ = -1;
};

} // namespace ssao
