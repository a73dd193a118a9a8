#include "techniques/ao_pass.h"

#include "gl/shader_library.h"
#include "passes/back_face_pass.h"
#include "passes/guard_band_pass.h"
#include "passes/position_pyramid_pass.h"
#include "scene/camera.h"
#include "techniques/ao_common.h"
#include "techniques/noise/blue_noise.h"

namespace ssao {

ResourceDesc aoRawOutput(const Chain& chain, const Settings& s) {
    ResourceDesc out = describe(chain.res("ao.raw"), GL_R32F, 1, Display::Unit,
                                "AO of the technique before denoising (1 = open, 0 = fully occluded)");
    out.scale = resolutionScale(s.ao.resolution);
    return out;
}

gpu::AoCommon aoCommonFor(const Settings& s, const FrameInfo& f, AoNoise noise, float pyramidOffset) {
    // A radius in pixels means displayed pixels, also while the app renders reduced.
    const float upp = unitsPerPixelAtUnitDepth(f.constants.proj, f.height) * f.displayScale;
    const float scale = resolutionScale(s.ao.resolution);
    const glm::ivec2 target(scaledSize(f.width, scale), scaledSize(f.height, scale));
    gpu::AoCommon c = packAoCommon(s.ao, 2.0f * f.sceneRadius, upp, target, s.skip.sky,
                                   s.gbuffer.normalFormat == TargetFormat::RGBA8);
    packNoise(c, noise);
    c.estimator.w = pyramidOffset; // taps d px away read MIP log2(d) - this (0: no pyramid)
    // Taps off the frame read the band; taps' thickness from the back layer (bindings.h bits).
    c.flags.w = float((GuardBandPass::bandOf(s) > 0 ? SSAO_AO_BAND : 0) | (BackFacePass::on(s) ? SSAO_AO_BACK_DEPTH : 0));
    return c;
}

AoBindings aoBindings(const Settings& s, AoNoise noise, bool pyramid, bool band) {
    AoBindings b;
    b.guardBand = band && GuardBandPass::bandOf(s) > 0;
    b.backDepth = band && BackFacePass::on(s);
    b.gbufferNormals = s.ao.normals == NormalSource::GBuffer;
    b.blueNoise = noise == AoNoise::Blue;
    b.pyramid = pyramid;
    return b;
}

void declareAoInputs(PassBuilder& b, const Chain& chain, const Settings& s, const AoBindings& bind,
                     const std::string& positions) {
    b.read(positions);
    if (bind.gbufferNormals) b.read("gbuffer.normal"); // else rebuilt from positions
    if (bind.pyramid) b.read(PositionPyramidPass::kOutput);
    if (bind.guardBand) b.read(GuardBandPass::kOutput);
    if (bind.backDepth) b.read(BackFacePass::kOutput);
    b.write(aoRawOutput(chain, s));
}

void AoShared::bind(PassContext& ctx, const AoBindings& bind, const std::string& pass) {
    if (bind.gbufferNormals) ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    if (bind.blueNoise) {
        if (!blueNoise_) { // made on first use: void and cluster takes a moment (techniques/noise)
            blueNoise_ = gl::Texture2D(kBlueNoiseSize, kBlueNoiseSize, GL_RG32F, pass + ".blue_noise");
            blueNoise_.setWrap(GL_REPEAT);
            glTextureSubImage2D(blueNoise_.id(), 0, 0, 0, kBlueNoiseSize, kBlueNoiseSize, GL_RG, GL_FLOAT,
                                blueNoise64Rg().data());
        }
        blueNoise_.bind(SSAO_TEX_BLUE_NOISE);
    }
    if (bind.pyramid) ctx.in(PositionPyramidPass::kOutput).bind(SSAO_TEX_POSITION_MIPS);
    if (bind.guardBand) ctx.in(GuardBandPass::kOutput).bind(SSAO_TEX_POSITION_BAND);
    if (bind.backDepth) ctx.in(BackFacePass::kOutput).bind(SSAO_TEX_BACK_DEPTH);
}

gl::Defines aoFeatureDefines(const gpu::AoCommon& c) {
    gl::Defines defs;
    const int inputs = int(c.flags.w);
    if (c.estimator.w > 0.0f) defs.push_back({"AO_PYRAMID", "1"});
    if (inputs & SSAO_AO_BAND) defs.push_back({"AO_BAND", "1"});
    if (inputs & SSAO_AO_BACK_DEPTH) defs.push_back({"AO_BACK_DEPTH", "1"});
    if (int(c.estimator.z) == SSAO_NORMALS_DEPTH) defs.push_back({"AO_NORMALS_DEPTH", "1"});
    defs.push_back({"AO_NOISE", std::to_string(int(c.estimator.y))}); // the kind as a constant (noise.glsl)
    if (c.estimator.x == 1.0f) defs.push_back({"AO_POWER_ONE", "1"});
    return defs;
}

void AoShared::draw(PassContext& ctx, const Chain& chain, const std::string& shader, const gpu::AoCommon& common,
                    bool inspect) {
    gl::Defines defs = aoFeatureDefines(common);
    if (inspect)
        defs.push_back({"INSPECT", "1"});
    else
        ctx.bindOutputs({chain.res("ao.raw")});
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", shader, defs));
    ctx.drawFullscreen();
}

bool AoShared::inspect(PassContext& ctx, const Chain& chain, glm::ivec2 pixel, PixelInspection& out,
                       const std::function<void()>& drawInspect) {
    const glm::ivec2 size = ctx.size(chain.res("ao.raw"));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return false;
    probe_.run(pixel, size, drawInspect, out);
    return true;
}

} // namespace ssao
