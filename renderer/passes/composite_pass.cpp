#include "passes/composite_pass.h"

#include "gl/shader_library.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

void CompositePass::setup(PassBuilder& b, const Settings& s) const {
    b.read("gbuffer.position");
    b.read("gbuffer.normal");
    b.read("gbuffer.albedo");
    if (s.composite.useAo) b.read(chain().res("ao.denoised")); // AO off: the AO chain is not needed
    b.write(describe(chain().res("composite"), GL_RGBA8, 3, Display::Color,
                     "the lit frame: ambient * albedo * AO + one point light, display gamma"));
}

CompositeConfig CompositePass::config(const Settings& s, const FrameInfo& f) const {
    CompositeConfig c{};
    c.frame = withoutFrameIndex(f.constants);
    c.ambient = s.composite.ambient;
    c.light = s.composite.light;
    c.useAo = s.composite.useAo;
    c.normalUnorm = s.gbuffer.normalFormat == TargetFormat::RGBA8;
    return c;
}

void CompositePass::run(PassContext& ctx, const CompositeConfig& c) {
    gl::Defines defs;
    if (c.normalUnorm) defs.push_back({"NORMAL_UNORM", "1"});
    GLuint prog = ctx.shaders.program("passes/fullscreen.vert", "passes/composite.frag", defs);
    glUseProgram(prog);
    glProgramUniform2f(prog, 0, c.ambient, c.light);
    glProgramUniform1f(prog, 1, c.useAo ? 1.0f : 0.0f);
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    ctx.in("gbuffer.albedo").bind(SSAO_TEX_ALBEDO);
    if (c.useAo)
        ctx.in(chain().res("ao.denoised")).bind(SSAO_TEX_AO);
    else
        glBindTextureUnit(SSAO_TEX_AO, 0);
    ctx.bindOutputs({chain().res("composite")});
    ctx.drawFullscreen();
}

} // namespace ssao
