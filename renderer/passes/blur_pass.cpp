#include "passes/blur_pass.h"

#include "ssao/constants.h"

namespace ssao {

void BlurPass::run(const FrameInputs& in) {
    if (!fboOut_ || out_.width() != in.width || out_.height() != in.height) {
        fboTmp_.reset();
        fboOut_.reset();
        tmp_ = gl::Texture2D(in.width, in.height, GL_R32F, "blur.tmp");
        out_ = gl::Texture2D(in.width, in.height, GL_R32F, "blur.ao");
        fboTmp_ = std::make_unique<gl::Framebuffer>(std::vector<const gl::Texture2D*>{&tmp_}, nullptr, "blur.x");
        fboOut_ = std::make_unique<gl::Framebuffer>(std::vector<const gl::Texture2D*>{&out_}, nullptr, "blur.y");
    }
    glUseProgram(in.shaders.program("passes/fullscreen.vert", "passes/blur.frag"));
    for (int dir = 0; dir < 2; ++dir) {
        if (!ubo_[dir]) ubo_[dir] = gl::UniformBuffer(sizeof(gpu::BlurConstants), dir ? "blur.y.constants" : "blur.x.constants");
        const gpu::BlurConstants c = packBlurConstants(in.settings.blur, dir);
        ubo_[dir].upload(&c, sizeof c);
        ubo_[dir].bind(SSAO_UBO_BLUR);
        (dir == 0 ? ssao_.aoRaw() : tmp_).bind(SSAO_TEX_AO);
        (dir == 0 ? fboTmp_ : fboOut_)->bind();
        in.triangle.draw();
    }
}

} // namespace ssao
