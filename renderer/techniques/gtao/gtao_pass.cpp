#include "techniques/gtao/gtao_pass.h"

#include "techniques/gtao/pack.h"

namespace ssao {

void GtaoPass::setup(PassBuilder& b, const Settings& s) const {
    declarePositionsNormals(b, s, "gtao");
}

std::string GtaoPass::prepare(PassContext& ctx) {
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::GtaoConstants), name() + ".constants");
    const gpu::GtaoConstants c = packGtaoConstants(ctx.settings.gtao, common(ctx), normalUnorm(ctx));
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);
    bindPositionsNormals(ctx);
    return "techniques/gtao/gtao.frag";
}

} // namespace ssao
