#include "techniques/gtao/gtao_pass.h"

#include "gl/shader_library.h"
#include "scene/camera.h"
#include "techniques/ao_common.h"
#include "techniques/gtao/pack.h"

namespace ssao {

void GtaoPass::setup(PassBuilder& b, const Settings& s) const {
    b.read("gbuffer.position");
    b.read("gbuffer.normal");
    ResourceDesc out = describe(branch().res("ao.raw"), GL_R32F, 1, Display::Unit,
                                "AO of the technique before denoising (1 = open, 0 = fully occluded)");
    out.scale = resolutionScale(s.ao.resolution);
    b.write(out);
    b.settings("ao");
    b.settings("gtao");
    b.usesScene();  // scene-relative radius
    b.usesCamera(); // projection: the radius in pixels
}

void GtaoPass::draw(PassContext& ctx, bool inspect) {
    const Settings& s = ctx.settings;
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::GtaoConstants), name() + ".constants");
    const std::string out = branch().res("ao.raw");
    const glm::ivec2 size = ctx.size(out);
    const FrameInfo& f = ctx.frame;
    const glm::mat4 proj = f.camera->projection(float(f.width) / float(f.height));
    const float upp = unitsPerPixelAtUnitDepth(proj, f.height) * f.displayScale;
    const gpu::AoCommon common = packAoCommon(s.ao, 2.0f * f.sceneRadius, upp, size);
    const bool unorm = ctx.desc("gbuffer.normal").format == GL_RGBA8;
    const gpu::GtaoConstants c = packGtaoConstants(s.gtao, common, unorm);
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    gl::Defines defs;
    if (inspect)
        defs.push_back({"INSPECT", "1"});
    else
        ctx.bindOutputs({out});
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "techniques/gtao/gtao.frag", defs));
    ctx.drawFullscreen();
}

void GtaoPass::execute(PassContext& ctx) {
    draw(ctx, false);
}

bool GtaoPass::inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) {
    const glm::ivec2 size = ctx.size(branch().res("ao.raw"));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return false;
    probe_.run(
        pixel, size, [&] { draw(ctx, true); }, out);
    return true;
}

} // namespace ssao
