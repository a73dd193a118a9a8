#include "techniques/ao_pass.h"

#include "gl/shader_library.h"
#include "graph/gbuffer_layers.h"
#include "scene/camera.h"
#include "techniques/ao_common.h"
#include "techniques/noise/blue_noise.h"
#include "techniques/technique.h"

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
    c.flags.w = float((s.gbuffer.guardBandPx > 0 ? SSAO_AO_BAND : 0) |
                      (s.gbuffer.backFaces ? SSAO_AO_BACK_DEPTH : 0) |
                      (s.gbuffer.secondLayer ? SSAO_AO_SECOND_LAYER : 0));
    return c;
}

AoBindings aoBindings(const Settings& s, AoNoise noise, bool pyramid, bool band) {
    AoBindings b;
    b.guardBand = band && s.gbuffer.guardBandPx > 0;
    b.backDepth = band && s.gbuffer.backFaces;
    b.secondLayer = band && s.gbuffer.secondLayer;
    b.gbufferNormals = s.ao.normals == NormalSource::GBuffer;
    b.blueNoise = noise == AoNoise::Blue;
    b.pyramid = pyramid;
    b.deinterleave = deinterleaves(s);
    return b;
}

void declareAoInputs(PassBuilder& b, const Chain& chain, const Settings& s, const AoBindings& bind,
                     const std::string& positions) {
    b.read(positions);
    if (bind.gbufferNormals) b.read("gbuffer.normal"); // else rebuilt from positions
    if (bind.pyramid) b.read(gbuffer::kPositionMips);
    if (bind.guardBand) b.read(gbuffer::kGuardBand);
    if (bind.backDepth) b.read(gbuffer::kBackDepth);
    if (bind.secondLayer) b.read(gbuffer::kSecondLayer);
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
    if (bind.pyramid) ctx.in(gbuffer::kPositionMips).bind(SSAO_TEX_POSITION_MIPS);
    if (bind.guardBand) ctx.in(gbuffer::kGuardBand).bind(SSAO_TEX_POSITION_BAND);
    if (bind.backDepth) ctx.in(gbuffer::kBackDepth).bind(SSAO_TEX_BACK_DEPTH);
    if (bind.secondLayer) ctx.in(gbuffer::kSecondLayer).bind(SSAO_TEX_SECOND_LAYER);
}

gl::Defines aoFeatureDefines(const gpu::AoCommon& c) {
    gl::Defines defs;
    const int inputs = int(c.flags.w);
    if (c.estimator.w > 0.0f) defs.push_back({"AO_PYRAMID", "1"});
    if (inputs & SSAO_AO_BAND) defs.push_back({"AO_BAND", "1"});
    if (inputs & SSAO_AO_BACK_DEPTH) defs.push_back({"AO_BACK_DEPTH", "1"});
    if (inputs & SSAO_AO_SECOND_LAYER) defs.push_back({"AO_SECOND_LAYER", "1"});
    if (int(c.estimator.z) == SSAO_NORMALS_DEPTH) defs.push_back({"AO_NORMALS_DEPTH", "1"});
    defs.push_back({"AO_NOISE", std::to_string(int(c.estimator.y))}); // the kind as a constant (noise.glsl)
    if (c.estimator.x == 1.0f) defs.push_back({"AO_POWER_ONE", "1"});
    return defs;
}

void AoShared::draw(PassContext& ctx, const Chain& chain, const std::string& shader, const gpu::AoCommon& common,
                    const AoBindings& bind, const gpu::FrameConstants& frame, bool inspect) {
    gl::Defines defs = aoFeatureDefines(common);
    if (bind.deinterleave) defs.push_back({"AO_DEINTERLEAVED", "1"});
    if (inspect)
        defs.push_back({"INSPECT", "1"});
    else if (!bind.deinterleave)
        ctx.bindOutputs({chain.res("ao.raw")});
    const GLuint program = ctx.shaders.program("passes/fullscreen.vert", shader, defs);
    auto fullscreen = [&] { ctx.drawFullscreen(); };
    if (!bind.deinterleave) {
        glUseProgram(program);
        ctx.drawFullscreen();
        return;
    }
    if (inspect) { // the layers of the last run: the probe's pixel is a texel of inspectLayer_
        glUseProgram(program);
        deinterleaver_.saveFrame();
        deinterleaver_.bindLayer(inspectLayer_, program);
        ctx.drawFullscreen();
        deinterleaver_.restoreFrame();
        return;
    }
    deinterleaver_.split(ctx.shaders.program("passes/fullscreen.vert", "passes/deinterleave.frag"),
                         ctx.in("gbuffer.position"), bind.gbufferNormals ? &ctx.in("gbuffer.normal") : nullptr, frame,
                         fullscreen);
    deinterleaver_.drawLayers(program, fullscreen);
    deinterleaver_.restoreFrame();
    ctx.bindOutputs({chain.res("ao.raw")});
    deinterleaver_.merge(ctx.shaders.program("passes/fullscreen.vert", "passes/reinterleave.frag"), fullscreen);
}

bool AoShared::inspect(PassContext& ctx, const Chain& chain, glm::ivec2 pixel, PixelInspection& out,
                       bool deinterleaved, const std::function<void()>& drawInspect) {
    const glm::ivec2 size = ctx.size(chain.res("ao.raw"));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return false;
    if (!deinterleaved) {
        probe_.run(pixel, size, drawInspect, out);
        return true;
    }
    // Pixel (x, y from the top) is texel (x / 4, y' / 4) of layer (x & 3, y' & 3), y' = its row from
    // the bottom (GL); the probe takes rows from the top of the layer.
    const int yGl = size.y - 1 - pixel.y;
    const glm::ivec2 layer = Deinterleaver::layerSize(size.x, size.y);
    inspectLayer_ = (pixel.x & 3) + Deinterleaver::kSide * (yGl & 3);
    const glm::ivec2 texel(pixel.x >> 2, layer.y - 1 - (yGl >> 2));
    probe_.run(texel, layer, drawInspect, out);
    out.pixel = pixel;
    for (auto& t : out.taps) t.uv = Deinterleaver::frameUv(t.uv, inspectLayer_, size.x, size.y);
    return true;
}

} // namespace ssao
