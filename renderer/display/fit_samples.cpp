#include "display/fit_samples.h"

#include "gl/shader_library.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

std::vector<FitSample> FitSamplePicker::pick(const gl::Texture2D& src, const gl::Texture2D& mask,
                                             gl::ShaderLibrary& shaders, const gl::FullscreenTriangle& tri) {
    const size_t pixels = size_t(src.width()) * size_t(src.height());
    const size_t stride = fitStride(pixels);
    const size_t count = (pixels + stride - 1) / stride; // p = 0, stride, ... < pixels
    const int rows = int((count + kWidth - 1) / kWidth);
    target_.ensure(kWidth, rows, GL_RGBA32F, "view.fit_samples");
    target_.bind();
    const GLuint prog = shaders.program("passes/fullscreen.vert", "display/fit_samples.frag");
    glUseProgram(prog);
    glProgramUniform1ui(prog, 0, GLuint(stride));
    glProgramUniform1ui(prog, 1, GLuint(count));
    glProgramUniform1ui(prog, 2, GLuint(kWidth));
    src.bind(SSAO_TEX_VIEW_SOURCE);
    mask.bind(SSAO_TEX_VIEW_MASK);
    tri.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // Rows in GL order are output rows in order (texel i at row i / kWidth from the bottom).
    const std::vector<float> raw = target_.texture().readFloats(4);
    std::vector<FitSample> out(count);
    for (size_t i = 0; i < count; ++i)
        out[i] = FitSample(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], raw[4 * i + 3]);
    return out;
}

} // namespace ssao
