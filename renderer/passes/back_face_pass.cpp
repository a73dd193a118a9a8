#include "passes/back_face_pass.h"

#include "gl/shader_library.h"
#include "passes/gbuffer_pass.h"

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
    const bool reversed = c.frame.camera.y != 0.0f;
    const SceneDrawState state(reversed, 1); // no face culling: facing by the normal, in the shader
    const glm::mat4 viewProj = c.frame.proj * c.frame.view;
    ctx.scene()->draw(scenePrograms(ctx, "passes/gbuffer.vert", "passes/back_faces.frag", {}, -1),
                      {&viewProj, reversed, c.cull != 0, false}); // the back faces are what it keeps
}

} // namespace ssao
