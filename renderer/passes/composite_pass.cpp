#include "passes/composite_pass.h"

#include "gl/shader_library.h"
#include "passes/denoise_weights.h"
#include "techniques/ao_common.h"
#include "techniques/technique.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

bool CompositePass::fusesUpsample(const Settings& s) const {
    return fuseAllowed_ && s.skip.fusedUpsample && s.composite.useAo && resolutionScale(s.ao.resolution) < 1.0f &&
           effectiveDenoise(s).upsample == DenoiseUpsample::Joint && !s.temporal.enabled;
}

// The denoiser's output at the AO's resolution (passes/denoise_pass.cpp), or the raw AO without one.
static bool reducedIsRaw(const Settings& s) { return effectiveDenoise(s).kind == DenoiseKind::None; }

void CompositePass::setup(PassBuilder& b, const Settings& s) const {
    b.read("gbuffer.position");
    b.read("gbuffer.normal");
    b.read("gbuffer.albedo");
    if (fusesUpsample(s)) {
        b.read(reducedAo(reducedIsRaw(s)));
        b.read("gbuffer.depth");
    } else if (s.composite.useAo) {
        b.read(chain().res("ao.denoised")); // AO off: the AO chain is not needed
    }
    ResourceDesc out = describe(chain().res("composite"), GL_RGBA8, 3, Display::Color,
                                "the lit frame: ambient * albedo * AO + one point light, display gamma");
    if (!fusesUpsample(s)) out.maxWidth = displayWidth_; // setDisplayWidth
    b.write(out);
}

CompositeConfig CompositePass::config(const Settings& s, const FrameInfo& f) const {
    CompositeConfig c{};
    c.frame = withoutFrameIndex(f.constants);
    c.ambient = s.composite.ambient;
    c.light = s.composite.light;
    c.useAo = s.composite.useAo;
    c.normalUnorm = s.gbuffer.normalFormat == TargetFormat::RGBA8;
    c.fused = fusesUpsample(s);
    if (c.fused) c.up = packJointUpsampleConstants(), c.reducedRaw = reducedIsRaw(s);
    return c;
}

void CompositePass::run(PassContext& ctx, const CompositeConfig& c) {
    gl::Defines defs;
    if (c.normalUnorm) defs.push_back({"NORMAL_UNORM", "1"});
    if (c.fused) defs.push_back({"FUSED_UPSAMPLE", "1"});
    GLuint prog = ctx.shaders.program("passes/fullscreen.vert", "passes/composite.frag", defs);
    glUseProgram(prog);
    glProgramUniform2f(prog, 0, c.ambient, c.light);
    glProgramUniform1f(prog, 1, c.useAo ? 1.0f : 0.0f);
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    ctx.in("gbuffer.albedo").bind(SSAO_TEX_ALBEDO);
    if (c.fused) {
        if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::DenoiseConstants), name() + ".upsample.constants");
        ubo_.upload(&c.up, sizeof c.up);
        ubo_.bind(SSAO_UBO_DENOISE);
        ctx.in(reducedAo(c.reducedRaw)).bind(SSAO_TEX_AO);
        gl::Sampler::unbind(SSAO_TEX_AO); // texelFetch: whole AO texels
        ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    } else if (c.useAo) {
        ctx.in(chain().res("ao.denoised")).bind(SSAO_TEX_AO);
    } else {
        glBindTextureUnit(SSAO_TEX_AO, 0);
    }
    ctx.bindOutputs({chain().res("composite")});
    ctx.drawFullscreen();
}

} // namespace ssao
