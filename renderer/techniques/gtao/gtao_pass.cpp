#include "techniques/gtao/gtao_pass.h"

#include "techniques/gtao/pack.h"

namespace ssao {

void GtaoPass::setup(PassBuilder& b, const Settings& s) const {
    b.read("gbuffer.position");
    b.read("gbuffer.normal");
    b.write(rawOutput(s));
    b.settings("ao");
    b.settings("gtao");
    b.usesScene();  // scene-relative radius
    b.usesCamera(); // projection: the radius in pixels
}

std::string GtaoPass::prepare(PassContext& ctx) {
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::GtaoConstants), name() + ".constants");
    const gpu::GtaoConstants c = packGtaoConstants(ctx.settings.gtao, common(ctx), normalUnorm(ctx));
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    return "techniques/gtao/gtao.frag";
}

} // namespace ssao
