#include "passes/denoise_pass.h"

#include "gl/shader_library.h"
#include "passes/denoise_weights.h"
#include "techniques/ao_common.h"

#include <algorithm>

namespace ssao {

void DenoisePass::setup(PassBuilder& b, const Settings& s) const {
    b.read(branch().res("ao.raw"));
    ResourceDesc tmp =
        describe(branch().res("denoise.tmp"), GL_R32F, 1, Display::Unit, "x pass of the denoiser");
    // The bilateral's passes all run at full resolution (its first pass upsamples jointly).
    const bool bilateral = s.denoise.kind == DenoiseKind::Bilateral;
    tmp.scale = bilateral ? 1.0f : resolutionScale(s.ao.resolution);
    tmp.internal = true;
    if (bilateral || s.temporal.enabled || s.skip.sky) b.read("gbuffer.depth");
    b.settings("skip.sky"); // its last pass skips sky pixels
    if (bilateral) b.read("gbuffer.normal");
    if (s.temporal.enabled) {
        b.settings("temporal");
        b.usesCamera(); // reprojection
    }
    b.write(tmp);
    b.write(describe(branch().res("ao.denoised"), GL_R32F, 1, Display::Unit,
                     "AO after the denoise stage, at full resolution (what the composite uses)"));
    b.settings("denoise");
}

void DenoisePass::execute(PassContext& ctx) {
    if (!linear_) linear_ = gl::Sampler(GL_LINEAR, GL_CLAMP_TO_EDGE, name() + ".upsample");
    if (ctx.settings.denoise.kind == DenoiseKind::Bilateral)
        bilateral(ctx);
    else
        separable(ctx);
    if (ctx.settings.temporal.enabled) temporal_.run(ctx, branch().res("ao.denoised"), name());
}

void DenoisePass::separable(PassContext& ctx) {
    const std::string raw = branch().res("ao.raw"), tmp = branch().res("denoise.tmp"),
                      out = branch().res("ao.denoised");
    const bool upsample = ctx.size(tmp) != ctx.size(out);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/denoise.frag"));
    if (ctx.settings.skip.sky) ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    for (int dir = 0; dir < 2; ++dir) {
        if (!ubo_[dir])
            ubo_[dir] =
                gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + (dir ? ".y" : ".x") + ".constants");
        const gpu::DenoiseConstants c = packDenoiseConstants(ctx.settings.denoise, dir, dir == 1 && ctx.settings.skip.sky);
        ubo_[dir].upload(&c, sizeof c);
        ubo_[dir].bind(SSAO_UBO_DENOISE);
        ctx.in(dir == 0 ? raw : tmp).bind(SSAO_TEX_AO);
        // Reduced-resolution AO is brought to full size bilinearly by the y pass; the centred box
        // reads between texels in both passes.
        const bool centred = ctx.settings.denoise.kind == DenoiseKind::Box4Centred;
        if ((dir == 1 && upsample) || centred)
            linear_.bind(SSAO_TEX_AO);
        else
            gl::Sampler::unbind(SSAO_TEX_AO);
        ctx.bindOutputs({dir == 0 ? tmp : out});
        ctx.drawFullscreen();
    }
    gl::Sampler::unbind(SSAO_TEX_AO);
}

void DenoisePass::bilateral(PassContext& ctx) {
    const std::string raw = branch().res("ao.raw"), tmp = branch().res("denoise.tmp"),
                      out = branch().res("ao.denoised");
    if (!ubo_[0]) ubo_[0] = gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + ".x.constants");
    const bool unorm = ctx.desc("gbuffer.normal").format == GL_RGBA8;
    const gpu::DenoiseConstants c = packBilateralConstants(ctx.settings.denoise, unorm);
    ubo_[0].upload(&c, sizeof c);
    ubo_[0].bind(SSAO_UBO_DENOISE);
    ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    gl::Sampler::unbind(SSAO_TEX_AO);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/denoise_bilateral.frag"));
    // Alternate targets so the last pass lands in ao.denoised: n = 3 is raw → out → tmp → out.
    const int n = std::clamp(ctx.settings.denoise.passes, 1, 3);
    std::string input = raw;
    for (int i = 0; i < n; ++i) {
        const std::string target = (n - 1 - i) % 2 == 0 ? out : tmp;
        ctx.in(input).bind(SSAO_TEX_AO);
        ctx.bindOutputs({target});
        ctx.drawFullscreen();
        input = target;
    }
}

} // namespace ssao
