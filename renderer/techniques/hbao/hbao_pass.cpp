#include "techniques/hbao/hbao_pass.h"

#include "techniques/hbao/pack.h"

namespace ssao {

void HbaoPass::setup(PassBuilder& b, const Settings& s) const {
    declarePositionsNormals(b, s, "hbao");
}

std::string HbaoPass::prepare(PassContext& ctx) {
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::HbaoConstants), name() + ".constants");
    const gpu::HbaoConstants c = packHbaoConstants(ctx.settings.hbao, common(ctx), normalUnorm(ctx));
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);
    bindPositionsNormals(ctx);
    return "techniques/hbao/hbao.frag";
}

} // namespace ssao
