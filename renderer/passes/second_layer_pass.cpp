#include "passes/second_layer_pass.h"

#include "gl/shader_library.h"
#include "passes/gbuffer_pass.h"

#include "../../shaders/include/bindings.h"

namespace ssao {

ResourceDesc secondLayerResource() {
    return describe(gbuffer::kSecondLayer, GL_R32F, 1, Display::Scalar,
                    "1 / linear depth of the nearest surface facing the camera behind the one seen (0 = none)",
                    "1 / scene units");
}

float secondLayerSeparation(const Settings& s, const FrameInfo& f) {
    return s.gbuffer.secondLayerSeparation * 2.0f * f.sceneRadius; // a fraction of the diagonal
}

void SecondLayerPass::setup(PassBuilder& b, const Settings&) const {
    b.read("gbuffer.position"); // the first layer, peeled away
    b.write(secondLayerResource());
    ResourceDesc z = describe("gbuffer.second_z", GL_DEPTH_COMPONENT32F, 1, Display::Scalar, "the second layer's depth test");
    z.internal = true;
    b.write(z);
}

SecondLayerConfig SecondLayerPass::config(const Settings& s, const FrameInfo& f) const {
    SecondLayerConfig c{};
    c.frame = withoutFrameIndex(f.constants);
    c.separation = secondLayerSeparation(s, f);
    c.cull = s.skip.cull;
    c.hiddenFaces = s.skip.hiddenFaces;
    c.sceneVersion = f.sceneVersion;
    return c;
}

void SecondLayerPass::run(PassContext& ctx, const SecondLayerConfig& c) {
    ctx.bindOutputs({kOutput, "gbuffer.second_z"});
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    const bool reversed = c.frame.camera.y != 0.0f;
    const SceneDrawState state(reversed, 1); // no face culling: facing by the normal, in the shader
    const ScenePrograms programs = scenePrograms(ctx, "passes/gbuffer.vert", "passes/second_layer.frag", {}, -1);
    for (GLuint program : {programs.opaque, programs.mask})
        if (program) glProgramUniform1f(program, SSAO_LOC_SECOND_LAYER_SEPARATION, c.separation);
    const glm::mat4 viewProj = c.frame.proj * c.frame.view;
    // Every draw: what the G-buffer's occlusion culling leaves out is what this layer is for.
    ctx.scene()->draw(programs, {&viewProj, reversed, c.cull != 0, c.hiddenFaces != 0});
}

} // namespace ssao
