#include "passes/ssao_pass.h"

#include "ssao/constants.h"
#include "ssao/kernel.h"

namespace ssao {

void SsaoPass::run(const FrameInputs& in) {
    target_.ensure(in.width, in.height, GL_R32F, "ssao.ao_raw");
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::SsaoConstants), "ssao.constants");
    if (noiseSeed_ != in.settings.ssao.seed) {
        // 4x4 tile of rotation vectors (seed 000), REPEAT-wrapped across the screen.
        noise_ = gl::Texture2D(4, 4, GL_RGBA32F, "ssao.noise");
        noise_.setWrap(GL_REPEAT);
        std::vector<glm::vec4> texels;
        for (auto& v : makeNoise(uint32_t(in.settings.ssao.seed)))
            texels.emplace_back(v, 0.0f);
        glTextureSubImage2D(noise_.id(), 0, 0, 0, 4, 4, GL_RGBA, GL_FLOAT, texels.data());
        noiseSeed_ = in.settings.ssao.seed;
    }
    const gpu::SsaoConstants c =
        packSsaoConstants(in.settings.ssao, in.settings.gbuffer, in.width, in.height);
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_SSAO);

    gbuffer_.position().bind(SSAO_TEX_POSITION);
    gbuffer_.normal().bind(SSAO_TEX_NORMAL);
    gbuffer_.depth().bind(SSAO_TEX_DEPTH);
    noise_.bind(SSAO_TEX_NOISE);
    target_.bind();
    glUseProgram(in.shaders.program("passes/fullscreen.vert", "passes/ssao.frag"));
    in.triangle.draw();
}

} // namespace ssao
