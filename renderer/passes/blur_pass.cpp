#include "passes/blur_pass.h"

#include "ssao/constants.h"

namespace ssao {

void BlurPass::run(const FrameInputs& in) {
    tmp_.ensure(in.width, in.height, GL_R32F, "blur.x");
    out_.ensure(in.width, in.height, GL_R32F, "blur.ao");
    glUseProgram(in.shaders.program("passes/fullscreen.vert", "passes/blur.frag"));
    for (int dir = 0; dir < 2; ++dir) {
        if (!ubo_[dir])
            ubo_[dir] =
                gl::UniformBuffer(sizeof(gpu::BlurConstants), dir ? "blur.y.constants" : "blur.x.constants");
        const gpu::BlurConstants c = packBlurConstants(in.settings.blur, dir);
        ubo_[dir].upload(&c, sizeof c);
        ubo_[dir].bind(SSAO_UBO_BLUR);
        (dir == 0 ? ssao_.aoRaw() : tmp_.texture()).bind(SSAO_TEX_AO);
        (dir == 0 ? tmp_ : out_).bind();
        in.triangle.draw();
    }
}

} // namespace ssao
