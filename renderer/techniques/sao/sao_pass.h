// SAO's pass: reads the G-buffer's positions and normals, writes ao.raw (techniques/ao_pass.h).
#pragma once
#include "techniques/ao_pass.h"

namespace ssao {

class SaoPass final : public AoPass {
  public:
    using AoPass::AoPass;
    void setup(PassBuilder& b, const Settings& s) const override;

  private:
    std::string prepare(PassContext& ctx) override;
    gl::UniformBuffer ubo_;
};

} // namespace ssao
