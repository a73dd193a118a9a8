#include "passes/denoise_pass.h"

#include "gl/shader_library.h"
#include "passes/denoise_weights.h"
#include "techniques/ao_common.h"
#include "techniques/technique.h"

#include <cmath>

namespace ssao {

bool copiesRaw(const Settings& s) {
    return effectiveDenoise(s).kind == DenoiseKind::None && resolutionScale(s.ao.resolution) == 1.0f;
}

void DenoisePass::setup(PassBuilder& b, const Settings& s) const {
    b.read(chain().res("ao.raw"));
    const DenoiseSettings d = effectiveDenoise(s);
    const bool bilateral = d.kind == DenoiseKind::Bilateral;
    const float scale = resolutionScale(s.ao.resolution);
    const bool joint = scale < 1.0f && d.upsample == DenoiseUpsample::Joint;
    ResourceDesc tmp =
        describe(chain().res("denoise.tmp"), GL_R32F, 1, Display::Unit, "x pass of the denoiser");
    // Filter upsampling: the bilateral's passes all run at full resolution (its first upsamples).
    tmp.scale = bilateral && !joint ? 1.0f : scale;
    tmp.internal = true;
    // The copy needs no depth: the raw AO is already 1 on the sky (run()).
    if (bilateral || joint || s.temporal.enabled || (s.skip.sky && !copiesRaw(s))) b.read("gbuffer.depth");
    if (bilateral || s.temporal.enabled) b.read("gbuffer.normal"); // temporal: the history's plane test
    if ((!joint || d.kind != DenoiseKind::None) && !copiesRaw(s)) b.write(tmp); // joint + none: the upsample alone
    if (joint && d.kind != DenoiseKind::None) { // the filter's last pass, before the upsample
        ResourceDesc low = describe(chain().res("denoise.low"), GL_R32F, 1, Display::Unit,
                                    "filtered AO at the AO's resolution, before the joint upsample");
        low.scale = scale;
        low.internal = true;
        b.write(low);
    }
    b.write(describe(chain().res("ao.denoised"), GL_R32F, 1, Display::Unit,
                     "AO after the denoise stage, at full resolution (what the composite uses)"));
}

DenoiseConfig DenoisePass::config(const Settings& s, const FrameInfo& f) const {
    DenoiseConfig c{};
    const DenoiseSettings d = effectiveDenoise(s); // auto: the technique's own
    c.bilateral = d.kind == DenoiseKind::Bilateral;
    c.skipSky = s.skip.sky;
    const int k = int(std::lround(1.0f / resolutionScale(s.ao.resolution))); // G-buffer texels per AO texel
    c.joint = k > 1 && d.upsample == DenoiseUpsample::Joint;
    if (c.joint) c.up = packJointUpsampleConstants();
    if (c.bilateral) {
        c.passes = d.passes;
        c.x = packBilateralConstants(d, s.gbuffer.normalFormat == TargetFormat::RGBA8, c.joint ? k : 0);
    } else if (c.joint) { // x and y at the AO's resolution (none: no pass), then the upsample
        c.bilinearTaps = d.kind == DenoiseKind::Box4Centred;
        c.passes = d.kind == DenoiseKind::None ? 0 : 2;
        c.x = packDenoiseConstants(d, 0);
        c.y = packDenoiseConstants(d, 1);
    } else {
        c.bilinearTaps = d.kind == DenoiseKind::Box4Centred;
        // none: one full-screen copy (bilinear upsample of reduced AO, sky to 1) instead of two.
        c.passes = d.kind == DenoiseKind::None ? 1 : 2;
        c.x = packDenoiseConstants(d, 0);
        c.y = packDenoiseConstants(d, 1, s.skip.sky); // the last pass skips sky pixels
    }
    c.copy = copiesRaw(s);
    c.temporal = temporalConfig(s, f);
    return c;
}

void DenoisePass::run(PassContext& ctx, const DenoiseConfig& c) {
    if (!linear_) linear_ = gl::Sampler(GL_LINEAR, GL_CLAMP_TO_EDGE, name() + ".upsample");
    const std::string raw = chain().res("ao.raw"), tmp = chain().res("denoise.tmp"),
                      low = chain().res("denoise.low"), out = chain().res("ao.denoised");
    if (c.joint) {
        std::string filtered = raw;
        if (c.bilateral) {
            bilateral(ctx, c, raw, tmp, low);
            filtered = low;
        } else if (c.passes == 2) {
            separable(ctx, c, low);
            filtered = low;
        }
        // Unwritten where nothing reads it: the composite then upsamples inline (composite_pass.h).
        if (ctx.needed(out))
            jointUpsample(ctx, c, filtered);
        else
            ctx.leaveUnwritten(out);
    } else if (c.bilateral) {
        bilateral(ctx, c, raw, tmp, out);
    } else if (c.copy) {
        // None at full resolution: the identity tap over ao.raw, whose sky is already 1 (the AO
        // passes write 1 there, AO_SKY_EARLY_OUT / AO_RESULT) and whose values are already <= 1
        // (aoFinish): the same texels copied, without a fullscreen pass (a copy is a fraction of
        // its cost on llvmpipe).
        const glm::ivec2 size = ctx.size(out);
        glCopyImageSubData(ctx.in(raw).id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.in(out).id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                           size.x, size.y, 1);
    } else {
        separable(ctx, c, out);
    }
    if (c.temporal.enabled) temporal_.run(ctx, c.temporal, chain().res("ao.denoised"), name());
}

void DenoisePass::jointUpsample(PassContext& ctx, const DenoiseConfig& c, const std::string& input) {
    if (!ubo_[2]) ubo_[2] = gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + ".upsample.constants");
    ubo_[2].upload(&c.up, sizeof c.up);
    ubo_[2].bind(SSAO_UBO_DENOISE);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/upsample_joint.frag"));
    ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    ctx.in(input).bind(SSAO_TEX_AO);
    gl::Sampler::unbind(SSAO_TEX_AO); // texelFetch: whole AO texels
    ctx.bindOutputs({chain().res("ao.denoised")});
    ctx.drawFullscreen();
}

void DenoisePass::separable(PassContext& ctx, const DenoiseConfig& c, const std::string& out) {
    const std::string raw = chain().res("ao.raw"), tmp = chain().res("denoise.tmp");
    const bool upsample = ctx.size(tmp) != ctx.size(out);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/denoise.frag"));
    if (c.skipSky) ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    for (int dir = 2 - c.passes; dir < 2; ++dir) { // none: the y pass alone, from ao.raw
        if (!ubo_[dir])
            ubo_[dir] =
                gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + (dir ? ".y" : ".x") + ".constants");
        const gpu::DenoiseConstants& k = dir == 0 ? c.x : c.y;
        ubo_[dir].upload(&k, sizeof k);
        ubo_[dir].bind(SSAO_UBO_DENOISE);
        ctx.in(dir == 0 || c.passes == 1 ? raw : tmp).bind(SSAO_TEX_AO);
        // Reduced-resolution AO is brought to full size bilinearly by the y pass; the centred box
        // reads between texels in both passes.
        if ((dir == 1 && upsample) || c.bilinearTaps)
            linear_.bind(SSAO_TEX_AO);
        else
            gl::Sampler::unbind(SSAO_TEX_AO);
        ctx.bindOutputs({dir == 0 ? tmp : out});
        ctx.drawFullscreen();
    }
    gl::Sampler::unbind(SSAO_TEX_AO);
}

void DenoisePass::bilateral(PassContext& ctx, const DenoiseConfig& c, const std::string& raw,
                            const std::string& tmp, const std::string& out) {
    if (!ubo_[0]) ubo_[0] = gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + ".x.constants");
    ubo_[0].upload(&c.x, sizeof c.x);
    ubo_[0].bind(SSAO_UBO_DENOISE);
    ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    gl::Sampler::unbind(SSAO_TEX_AO);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/denoise_bilateral.frag"));
    // Alternate targets so the last pass lands in ao.denoised: n = 3 is raw → out → tmp → out.
    const int n = c.passes;
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
