// Kernel SSAO's pass: reads the G-buffer (positions or the depth buffer, normals), writes ao.raw
// (techniques/ao_pass.h). Its config: the constant block, the frame block, the shared bindings and
// its own choices (positions from depth, the rotation tile's seed).
#pragma once
#include "techniques/ao_pass.h"

#include "../../../shaders/techniques/kernel/layout.h"

namespace ssao {

SSAO_CONFIG_BEGIN
struct KernelConfig {
    gpu::KernelConstants constants;
    gpu::FrameConstants frame;
    AoBindings bind;
    int32_t positionsFromDepth; // reads gbuffer.zbuffer (seeds 000/001) instead of gbuffer.position
    int32_t noiseSeed;          // the 4x4 rotation tile's content
};
SSAO_CONFIG_END

class KernelPass final : public AoPass<KernelConfig> {
  public:
    using AoPass::AoPass;
    void setup(PassBuilder& b, const Settings& s) const override;
    KernelConfig config(const Settings& s, const FrameInfo& f) const override;

  private:
    std::string prepare(PassContext& ctx, const KernelConfig& c) override;
    gl::Texture2D noise_;
    gl::UniformBuffer ubo_;
    int noiseSeed_ = -1;
};

} // namespace ssao
