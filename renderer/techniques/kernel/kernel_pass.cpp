#include "techniques/kernel/kernel_pass.h"

#include "gl/shader_library.h"
#include "scene/camera.h"
#include "techniques/ao_common.h"
#include "techniques/kernel/pack.h"
#include "techniques/kernel/sampling.h"

namespace ssao {

void KernelPass::setup(PassBuilder& b, const Settings& s) const {
    b.read(s.kernel.positionSource == PositionSource::Depth ? "gbuffer.zbuffer" : "gbuffer.position");
    b.read("gbuffer.normal");
    ResourceDesc out = describe(branch().res("ao.raw"), GL_R32F, 1, Display::Unit,
                                "AO of the technique before denoising (1 = open, 0 = fully occluded)");
    out.scale = resolutionScale(s.ao.resolution);
    b.write(out);
    b.settings("ao");
    b.settings("kernel");
    b.usesScene();  // scene-relative radius
    b.usesCamera(); // screen-space radius, projection
}

void KernelPass::draw(PassContext& ctx, bool inspect) {
    const Settings& s = ctx.settings;
    if (!ubo_) ubo_ = gl::UniformBuffer(sizeof(gpu::KernelConstants), name() + ".constants");
    if (noiseSeed_ != s.kernel.seed) {
        // 4x4 tile of rotation vectors (seed 000), REPEAT-wrapped across the screen.
        noise_ = gl::Texture2D(4, 4, GL_RGBA32F, name() + ".noise");
        noise_.setWrap(GL_REPEAT);
        std::vector<glm::vec4> texels;
        for (auto& v : makeNoise(uint32_t(s.kernel.seed)))
            texels.emplace_back(v, 0.0f);
        glTextureSubImage2D(noise_.id(), 0, 0, 0, 4, 4, GL_RGBA, GL_FLOAT, texels.data());
        noiseSeed_ = s.kernel.seed;
    }
    const std::string out = branch().res("ao.raw");
    const glm::ivec2 size = ctx.size(out);
    const FrameInfo& f = ctx.frame;
    const glm::mat4 proj = f.camera->projection(float(f.width) / float(f.height));
    // A radius in pixels means displayed pixels, also while the app renders reduced.
    const float upp = unitsPerPixelAtUnitDepth(proj, f.height) * f.displayScale;
    const gpu::AoCommon common = packAoCommon(s.ao, 2.0f * f.sceneRadius, upp, size);
    const bool unorm = ctx.desc("gbuffer.normal").format == GL_RGBA8;
    const gpu::KernelConstants c = packKernelConstants(s.kernel, common, unorm);
    ubo_.upload(&c, sizeof c);
    ubo_.bind(SSAO_UBO_AO);

    if (s.kernel.positionSource == PositionSource::Depth)
        ctx.in("gbuffer.zbuffer").bind(SSAO_TEX_DEPTH);
    else
        ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    noise_.bind(KERNEL_TEX_NOISE);
    gl::Defines defs;
    if (inspect)
        defs.push_back({"INSPECT", "1"});
    else
        ctx.bindOutputs({out});
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "techniques/kernel/kernel.frag", defs));
    ctx.drawFullscreen();
}

void KernelPass::execute(PassContext& ctx) {
    draw(ctx, false);
}

bool KernelPass::inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) {
    const glm::ivec2 size = ctx.size(branch().res("ao.raw"));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return false;
    probe_.run(
        pixel, size, [&] { draw(ctx, true); }, out);
    return true;
}

} // namespace ssao
