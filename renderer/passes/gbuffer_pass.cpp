#include "passes/gbuffer_pass.h"

#include "scene/gpu_scene.h"

namespace ssao {

GLenum glFormat(TargetFormat f) {
    switch (f) {
    case TargetFormat::RGBA16F:
        return GL_RGBA16F;
    case TargetFormat::RGBA32F:
        return GL_RGBA32F;
    case TargetFormat::RGBA8:
        return GL_RGBA8;
    }
    return GL_RGBA32F;
}

void GBufferPass::run(const FrameInputs& in) {
    const GBufferSettings& g = in.settings.gbuffer;
    if (!fbo_ || position_.width() != in.width || position_.height() != in.height ||
        g.positionFormat != built_.positionFormat || g.normalFormat != built_.normalFormat) {
        fbo_.reset();
        position_ = gl::Texture2D(in.width, in.height, glFormat(g.positionFormat), "gbuffer.position");
        normal_ = gl::Texture2D(in.width, in.height, glFormat(g.normalFormat), "gbuffer.normal");
        albedo_ = gl::Texture2D(in.width, in.height, GL_RGBA8, "gbuffer.albedo");
        linearDepth_ = gl::Texture2D(in.width, in.height, GL_R32F, "gbuffer.linear_depth");
        depth_ = gl::Texture2D(in.width, in.height, GL_DEPTH_COMPONENT32F, "gbuffer.depth");
        fbo_ = std::make_unique<gl::Framebuffer>(
            std::vector<const gl::Texture2D*>{&position_, &normal_, &albedo_, &linearDepth_}, &depth_,
            "gbuffer");
        built_ = g;
    }
    fbo_->bind();
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
        glClearNamedFramebufferfv(fbo_->id(), GL_COLOR, i, zero); // w = 0: sky
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo_->id(), GL_DEPTH, 0, &one);

    gl::Defines defs;
    if (g.normalFormat == TargetFormat::RGBA8) defs.push_back({"NORMAL_UNORM", "1"});
    glUseProgram(in.shaders.program("passes/gbuffer.vert", "passes/gbuffer.frag", defs));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); // glTF doubleSided and CAD winding: shade what is visible
    in.scene.draw(0);
    glDisable(GL_DEPTH_TEST);
}

} // namespace ssao
