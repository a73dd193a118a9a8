#include "passes/denoise_pass.h"

#include "gl/shader_library.h"
#include "passes/denoise_weights.h"
#include "techniques/ao_common.h"

namespace ssao {

void DenoisePass::setup(PassBuilder& b, const Settings& s) const {
    b.read(branch().res("ao.raw"));
    ResourceDesc tmp =
        describe(branch().res("denoise.tmp"), GL_R32F, 1, Display::Unit, "x pass of the denoiser");
    tmp.scale = resolutionScale(s.ao.resolution);
    tmp.internal = true;
    b.write(tmp);
    b.write(describe(branch().res("ao.denoised"), GL_R32F, 1, Display::Unit,
                     "AO after the denoise stage, at full resolution (what the composite uses)"));
    b.settings("denoise");
}

void DenoisePass::execute(PassContext& ctx) {
    if (!linear_) linear_ = gl::Sampler(GL_LINEAR, GL_CLAMP_TO_EDGE, name() + ".upsample");
    const std::string raw = branch().res("ao.raw"), tmp = branch().res("denoise.tmp"),
                      out = branch().res("ao.denoised");
    const bool upsample = ctx.size(tmp) != ctx.size(out);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/denoise.frag"));
    for (int dir = 0; dir < 2; ++dir) {
        if (!ubo_[dir])
            ubo_[dir] =
                gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + (dir ? ".y" : ".x") + ".constants");
        const gpu::DenoiseConstants c = packDenoiseConstants(ctx.settings.denoise, dir);
        ubo_[dir].upload(&c, sizeof c);
        ubo_[dir].bind(SSAO_UBO_DENOISE);
        ctx.in(dir == 0 ? raw : tmp).bind(SSAO_TEX_AO);
        // Reduced-resolution AO is brought to full size bilinearly by the y pass.
        if (dir == 1 && upsample)
            linear_.bind(SSAO_TEX_AO);
        else
            gl::Sampler::unbind(SSAO_TEX_AO);
        ctx.bindOutputs({dir == 0 ? tmp : out});
        ctx.drawFullscreen();
    }
    gl::Sampler::unbind(SSAO_TEX_AO);
}

} // namespace ssao
