#include "techniques/ao_pass.h"

#include "gl/shader_library.h"
#include "scene/camera.h"
#include "techniques/ao_common.h"
#include "techniques/noise/blue_noise.h"

namespace ssao {

ResourceDesc AoPass::rawOutput(const Settings& s) const {
    ResourceDesc out = describe(branch().res("ao.raw"), GL_R32F, 1, Display::Unit,
                                "AO of the technique before denoising (1 = open, 0 = fully occluded)");
    out.scale = resolutionScale(s.ao.resolution);
    return out;
}

void AoPass::declarePositionsNormals(PassBuilder& b, const Settings& s, const char* group) const {
    b.read("gbuffer.position");
    if (s.ao.normals == NormalSource::GBuffer) b.read("gbuffer.normal"); // else rebuilt from positions
    b.write(rawOutput(s));
    b.settings("ao");
    b.settings(group);
    b.settings("skip.sky");
    b.usesScene();  // scene-relative radius
    b.usesCamera(); // projection: the radius in pixels
    b.usesFrameIndex(); // noise
}

void AoPass::bindPositionsNormals(PassContext& ctx) const {
    ctx.in("gbuffer.position").bind(SSAO_TEX_POSITION);
    if (ctx.settings.ao.normals == NormalSource::GBuffer) ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
}

gpu::AoCommon AoPass::common(PassContext& ctx) const {
    const FrameInfo& f = ctx.frame;
    const glm::mat4 proj = f.camera->projection(float(f.width) / float(f.height));
    // A radius in pixels means displayed pixels, also while the app renders reduced.
    const float upp = unitsPerPixelAtUnitDepth(proj, f.height) * f.displayScale;
    return packAoCommon(ctx.settings.ao, 2.0f * f.sceneRadius, upp, ctx.size(branch().res("ao.raw")),
                        ctx.settings.skip.sky);
}

void AoPass::bindShared(PassContext& ctx, const gpu::AoCommon& c) {
    if (int(c.shape.y) == SSAO_NOISE_BLUE) {
        if (!blueNoise_) { // made on first use: void and cluster takes a moment (techniques/noise)
            blueNoise_ = gl::Texture2D(kBlueNoiseSize, kBlueNoiseSize, GL_RG32F, name() + ".blue_noise");
            blueNoise_.setWrap(GL_REPEAT);
            glTextureSubImage2D(blueNoise_.id(), 0, 0, 0, kBlueNoiseSize, kBlueNoiseSize, GL_RG, GL_FLOAT,
                                blueNoise64Rg().data());
        }
        blueNoise_.bind(SSAO_TEX_BLUE_NOISE);
    }
    if (c.shape.w > 0.0f) {
        pyramid_.build(ctx, ctx.in("gbuffer.position"));
        pyramid_.bind(SSAO_TEX_POSITION_MIPS);
    }
}

bool AoPass::normalUnorm(PassContext& ctx) const {
    return ctx.desc("gbuffer.normal").format == GL_RGBA8;
}

void AoPass::draw(PassContext& ctx, bool inspect) {
    const std::string frag = prepare(ctx); // may draw (the position pyramid): outputs bound after
    gl::Defines defs;
    if (inspect)
        defs.push_back({"INSPECT", "1"});
    else
        ctx.bindOutputs({branch().res("ao.raw")});
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", frag, defs));
    ctx.drawFullscreen();
}

bool AoPass::inspect(PassContext& ctx, glm::ivec2 pixel, PixelInspection& out) {
    const glm::ivec2 size = ctx.size(branch().res("ao.raw"));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return false;
    probe_.run(
        pixel, size, [&] { draw(ctx, true); }, out);
    return true;
}

} // namespace ssao
