#include "passes/back_face_pass.h"

#include "gl/shader_library.h"

namespace ssao {

void BackFacePass::setup(PassBuilder& b, const Settings&) const {
    b.write(describe(kOutput, GL_R32F, 1, Display::Scalar,
                     "linear view distance of the nearest surface facing away (0 = none): the far side of what is seen",
                     "scene units"));
    ResourceDesc z = describe("gbuffer.back_z", GL_DEPTH_COMPONENT32F, 1, Display::Scalar, "the back layer's depth test");
    z.internal = true;
    b.write(z);
}

BackFaceConfig BackFacePass::config(const Settings& s, const FrameInfo& f) const {
    BackFaceConfig c{};
    c.frame = withoutFrameIndex(f.constants);
    c.cull = s.skip.cull;
    c.sceneVersion = f.sceneVersion;
    return c;
}

void BackFacePass::run(PassContext& ctx, const BackFaceConfig& c) {
    ctx.bindOutputs({kOutput, "gbuffer.back_z"});
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(GLuint(fbo), GL_COLOR, 0, zero);
    const bool reversed = c.frame.camera.y != 0.0f; // as passes/gbuffer_pass.cpp draws
    const float clearDepth = reversed ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(GLuint(fbo), GL_DEPTH, 0, &clearDepth);
    struct Restore {
        bool reversed;
        ~Restore() {
            if (reversed) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
            glDisable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
        }
    } restore{reversed};
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glUseProgram(ctx.shaders.program("passes/gbuffer.vert", "passes/back_faces.frag", {}));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glDisable(GL_CULL_FACE); // facing by the normal, in the shader
    const glm::mat4 viewProj = c.frame.proj * c.frame.view;
    ctx.scene()->draw(-1, c.cull ? &viewProj : nullptr, reversed);
}

} // namespace ssao
