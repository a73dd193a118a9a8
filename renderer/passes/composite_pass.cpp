#include "passes/composite_pass.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

void CompositePass::run(const FrameInputs& in) {
    target_.ensure(in.width, in.height, GL_RGBA8, "composite");
    gl::Defines defs;
    if (in.settings.gbuffer.normalFormat == TargetFormat::RGBA8) defs.push_back({"NORMAL_UNORM", "1"});
    GLuint prog = in.shaders.program("passes/fullscreen.vert", "passes/composite.frag", defs);
    glUseProgram(prog);
    glProgramUniform2f(prog, 0, in.settings.composite.ambient, in.settings.composite.light);
    glProgramUniform1f(prog, 1, in.settings.composite.useAo ? 1.0f : 0.0f);
    gbuffer_.position().bind(SSAO_TEX_POSITION);
    gbuffer_.normal().bind(SSAO_TEX_NORMAL);
    gbuffer_.albedo().bind(SSAO_TEX_ALBEDO);
    blur_.ao().bind(SSAO_TEX_AO);
    target_.bind();
    in.triangle.draw();
}

} // namespace ssao
