#include "passes/guard_band_pass.h"

#include "gl/shader_library.h"
#include "passes/gbuffer_pass.h"

#include "../../shaders/include/bindings.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ssao {

glm::mat4 widenedProjection(const glm::mat4& proj, int width, int height, int band) {
    // Clip x' = x * W / (W + 2g): NDC spans W + 2g pixels of the frame's pixel size, and pixel
    // centres stay on the frame's grid shifted by g (the band is a whole number of pixels).
    const glm::vec3 s(float(width) / float(width + 2 * band), float(height) / float(height + 2 * band), 1.0f);
    return glm::scale(glm::mat4(1.0f), s) * proj;
}

void GuardBandPass::setup(PassBuilder& b, const Settings& s) const {
    ResourceDesc pos = describe(kOutput, glFormat(s.gbuffer.positionFormat), 3, Display::Vector,
                                "view-space positions of the frame and the guard band beyond it (taps off the "
                                "frame read it)", "scene units");
    pos.margin = band_;
    b.write(pos);
    ResourceDesc z = describe("gbuffer.guard_band_z", GL_DEPTH_COMPONENT32F, 1, Display::Scalar,
                              "the guard band's depth test");
    z.margin = band_;
    z.internal = true;
    b.write(z);
}

GuardBandConfig GuardBandPass::config(const Settings& s, const FrameInfo& f) const {
    GuardBandConfig c{};
    c.frame = withoutFrameIndex(f.constants);
    c.band = band_;
    c.frame.proj = widenedProjection(c.frame.proj, f.width, f.height, band_);
    c.frame.invProj = glm::inverse(c.frame.proj);
    const float w = float(f.width + 2 * band_), h = float(f.height + 2 * band_);
    c.frame.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    c.cull = s.skip.cull;
    c.hiddenFaces = s.skip.hiddenFaces;
    c.sceneVersion = f.sceneVersion;
    return c;
}

void GuardBandPass::run(PassContext& ctx, const GuardBandConfig& c) {
    ctx.bindOutputs({kOutput, "gbuffer.guard_band_z"});
    const bool reversed = c.frame.camera.y != 0.0f;
    const SceneDrawState state(reversed, 1);
    // The widened frame block for this draw only; the frame's own is bound again after it.
    GLint previous = 0;
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, SSAO_UBO_FRAME, &previous);
    frameUbo_.upload(&c.frame, sizeof c.frame);
    frameUbo_.bind(SSAO_UBO_FRAME);
    struct Restore {
        GLuint ubo;
        ~Restore() { glBindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_FRAME, ubo); }
    } restore{GLuint(previous)};
    const glm::mat4 viewProj = c.frame.proj * c.frame.view;
    ctx.scene()->draw(scenePrograms(ctx, "passes/gbuffer.vert", "passes/gbuffer.frag", {{"WRITE_POSITION", "0"}}, -1),
                      {&viewProj, reversed, c.cull != 0, c.hiddenFaces != 0});
}

} // namespace ssao
