#include "techniques/sao/sao_pass.h"

#include "techniques/sao/pack.h"

namespace ssao {

void SaoPass::setup(PassBuilder& b, const Settings& s) const {
    declarePositionsNormals(b, s, "sao");
}

std::string SaoPass::prepare(PassContext& ctx) {
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::SaoConstants), name() + ".constants");
    const gpu::SaoConstants c = packSaoConstants(ctx.settings.sao, common(ctx), normalUnorm(ctx));
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);
    bindPositionsNormals(ctx);
    return "techniques/sao/sao.frag";
}

} // namespace ssao
