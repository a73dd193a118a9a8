#include "passes/gbuffer_pass.h"

#include "gl/shader_library.h"
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

void GBufferPass::setup(PassBuilder& b, const Settings& s) const {
    const GBufferSettings& g = s.gbuffer;
    b.write(describe("gbuffer.position", glFormat(g.positionFormat), 3, Display::Vector,
                     "view-space position (camera at the origin, looking down -z)", "scene units"));
    ResourceDesc normal = describe("gbuffer.normal", glFormat(g.normalFormat), 3, Display::Direction,
                                   "view-space unit normal of the visible side");
    if (g.normalFormat == TargetFormat::RGBA8)
        normal.decodeScale = 2.0f, normal.decodeOffset = -1.0f; // (n+1)/2
    b.write(normal);
    b.write(describe("gbuffer.albedo", GL_RGBA8, 3, Display::Color, "base colour (glTF baseColorFactor)"));
    b.write(describe("gbuffer.depth", GL_R32F, 1, Display::Scalar, "linear view distance along -z (0 = sky)",
                     "scene units"));
    b.write(describe("gbuffer.zbuffer", GL_DEPTH_COMPONENT32F, 1, Display::Scalar,
                     "hardware depth in [0,1] (non-linear, 1 at near when reversed; seed 001 reconstructs positions from it)"));
    b.settings("gbuffer");
    b.usesScene();
    b.usesCamera();
}

void GBufferPass::execute(PassContext& ctx) {
    ctx.bindOutputs(
        {"gbuffer.position", "gbuffer.normal", "gbuffer.albedo", "gbuffer.depth", "gbuffer.zbuffer"});
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
        glClearNamedFramebufferfv(GLuint(fbo), GL_COLOR, i, zero); // w = 0: sky
    // Reversed depth (scene/camera.h): z_ndc in [0, 1] written as is, 1 at near, cleared to 0 (far)
    // and tested with GREATER; the other passes draw with the default clip control.
    const bool reversed = ctx.frame.camera->depth == DepthMode::Reversed;
    const float clearDepth = reversed ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(GLuint(fbo), GL_DEPTH, 0, &clearDepth);
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    struct RestoreClip {
        bool on;
        ~RestoreClip() {
            if (on) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        }
    } restoreClip{reversed};

    gl::Defines defs;
    if (ctx.settings.gbuffer.normalFormat == TargetFormat::RGBA8) defs.push_back({"NORMAL_UNORM", "1"});
    glUseProgram(ctx.shaders.program("passes/gbuffer.vert", "passes/gbuffer.frag", defs));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glDisable(GL_CULL_FACE); // glTF doubleSided and CAD winding: shade what is visible
    ctx.frame.scene->draw(0);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

} // namespace ssao
