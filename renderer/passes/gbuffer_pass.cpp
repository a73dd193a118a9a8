#include "passes/gbuffer_pass.h"

#include "gl/shader_library.h"
#include "passes/second_layer_pass.h"
#include "scene/gpu/gpu_scene.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

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
    if (keepsSecondLayer(s)) b.write(secondLayerResource());
}

bool GBufferPass::keepsSecondLayer(const Settings& s) {
    return s.gbuffer.secondLayer && s.gbuffer.secondLayerBuild == SecondLayerBuild::Previous;
}

GBufferConfig GBufferPass::config(const Settings& s, const FrameInfo& f) const {
    GBufferConfig c{};
    c.frame = withoutFrameIndex(f.constants);
    c.normalUnorm = s.gbuffer.normalFormat == TargetFormat::RGBA8;
    c.cull = s.skip.cull;
    c.skipUnused = s.skip.unusedTargets;
    c.hiddenFaces = s.skip.hiddenFaces;
    c.sceneVersion = f.sceneVersion;
    c.lod = f.lod;
    c.secondLayer = keepsSecondLayer(s);
    c.separation = c.secondLayer ? secondLayerSeparation(s, f) : 0.0f;
    // What the first layer hides is what the second layer is for: every draw is drawn.
    c.occluded = s.skip.occluded && !c.secondLayer;
    return c;
}

namespace {
// The colour targets in gbuffer.frag's order, with the define that makes it write each.
struct Target {
    const char* name;
    const char* define;
};
constexpr Target kTargets[] = {{"gbuffer.position", "WRITE_POSITION"},
                               {"gbuffer.normal", "WRITE_NORMAL"},
                               {"gbuffer.albedo", "WRITE_ALBEDO"},
                               {"gbuffer.depth", "WRITE_DEPTH"}};
} // namespace

void GBufferPass::run(PassContext& ctx, const GBufferConfig& c) {
    // Targets no live pass and no consumer reads are neither bound nor computed (skip.unused_targets).
    std::vector<std::string> outputs;
    gl::Defines defs;
    written_.clear();
    for (const Target& t : kTargets) {
        const bool reprojected = c.secondLayer && &t == &kTargets[0]; // the position: what the next frame reprojects
        if (c.skipUnused && !ctx.needed(t.name) && !reprojected) {
            ctx.leaveUnwritten(t.name);
            continue;
        }
        defs.push_back({t.define, std::to_string(outputs.size())}); // its colour attachment
        outputs.push_back(t.name);
        written_.push_back(t.name);
    }
    outputs.push_back("gbuffer.zbuffer"); // the depth test needs it
    ctx.bindOutputs(outputs);
    const bool reversed = c.frame.camera.y != 0.0f;
    const SceneDrawState state(reversed, int(outputs.size()) - 1); // every colour target; the depth
    if (c.normalUnorm) defs.push_back({"NORMAL_UNORM", "1"});
    if (c.secondLayer) defs.push_back({"SECOND_LAYER_PREVIOUS", "1"});
    const glm::mat4 viewProj = c.frame.proj * c.frame.view;
    // Location 0 is uBaseColor; without the albedo target it is compiled out (-1: ignored).
    const bool albedo = std::find(outputs.begin(), outputs.end(), "gbuffer.albedo") != outputs.end();
    const ScenePrograms programs = scenePrograms(ctx, "passes/gbuffer.vert", "passes/gbuffer.frag", defs, albedo ? 0 : -1);
    DrawOptions o{&viewProj, reversed, c.cull != 0, c.hiddenFaces != 0, c.lod};
    o.lodView = &c.frame.view; // each draw's own level (DrawOptions::lodView): all of it is in the config
    o.lodProjY = c.frame.proj[1][1];
    o.lodOrthographic = c.frame.camera.x != 0.0f;
    o.lodHeight = int(c.frame.viewport.y);
    if (c.occluded) {
        occlusion_.begin(ctx.scene()->drawCount(), c.sceneVersion,
                         ctx.shaders.program("passes/occlusion_box.vert", "passes/occlusion_box.frag"));
        o.occlusion = &occlusion_; // with it off the visible set waits, unchanged: it only ever guides the order
    }
    const bool hadPrevious = c.secondLayer && beginSecondLayer(ctx, c, programs);
    stats_ = ctx.scene()->draw(programs, o);
    if (!c.secondLayer) {
        previous_ = {}; // a frame drawn without it: the next one with it has no previous frame
        return;
    }
    keepPrevious(ctx, c);
    if (!hadPrevious) {
        // No previous frame to reproject (the first, a new size or scene): this frame's own first
        // layer is the previous one; drawn again, the depth test keeps the G-buffer as it is.
        beginSecondLayer(ctx, c, programs);
        o.occlusion = nullptr;
        ctx.scene()->draw(programs, o);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(SSAO_IMG_SECOND_LAYER, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

bool GBufferPass::beginSecondLayer(PassContext& ctx, const GBufferConfig& c, const ScenePrograms& programs) {
    const gl::Texture2D& layer = ctx.in(gbuffer::kSecondLayer);
    const gl::Texture2D& position = ctx.in("gbuffer.position");
    const float none = 0.0f; // the bits of 0.0f are 0: no surface
    glClearTexImage(layer.id(), 0, GL_RED, GL_FLOAT, &none);
    // The r32f layer is written as r32ui: image units match formats by size.
    glBindImageTexture(SSAO_IMG_SECOND_LAYER, layer.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    const bool valid = previous_.position && previous_.position.width() == position.width() &&
                       previous_.position.height() == position.height() &&
                       previous_.position.format() == position.format() && previous_.sceneVersion == c.sceneVersion;
    const glm::mat4 toPrevious = valid ? previous_.view * glm::inverse(c.frame.view) : glm::mat4(1.0f);
    const glm::mat4 proj = valid ? previous_.proj : c.frame.proj;
    const float separation = valid ? c.separation : INFINITY; // nothing lies behind an unknown first layer
    if (valid) previous_.position.bind(SSAO_TEX_PREVIOUS_POSITION);
    for (GLuint program : {programs.opaque, programs.mask}) {
        if (!program) continue;
        glProgramUniformMatrix4fv(program, SSAO_LOC_TO_PREVIOUS_VIEW, 1, GL_FALSE, glm::value_ptr(toPrevious));
        glProgramUniformMatrix4fv(program, SSAO_LOC_PREVIOUS_PROJ, 1, GL_FALSE, glm::value_ptr(proj));
        glProgramUniform1f(program, SSAO_LOC_SECOND_LAYER_SEPARATION, separation);
    }
    return valid;
}

void GBufferPass::keepPrevious(PassContext& ctx, const GBufferConfig& c) {
    const gl::Texture2D& position = ctx.in("gbuffer.position");
    if (!previous_.position || previous_.position.width() != position.width() ||
        previous_.position.height() != position.height() || previous_.position.format() != position.format())
        previous_.position = gl::Texture2D(position.width(), position.height(), position.format(), "gbuffer.previous_position");
    glCopyImageSubData(position.id(), GL_TEXTURE_2D, 0, 0, 0, 0, previous_.position.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       position.width(), position.height(), 1);
    previous_.view = c.frame.view;
    previous_.proj = c.frame.proj;
    previous_.sceneVersion = c.sceneVersion;
}

ScenePrograms scenePrograms(PassContext& ctx, const std::string& vert, const std::string& frag, gl::Defines defines,
                            GLint colorLocation) {
    ScenePrograms p;
    p.colorLocation = colorLocation;
    p.opaque = ctx.shaders.program(vert, frag, defines);
    if (ctx.scene()->hasMask()) {
        defines.push_back({"ALPHA_MASK", "1"});
        p.mask = ctx.shaders.program(vert, frag, defines);
    }
    return p;
}

SceneDrawState::SceneDrawState(bool reversed, int colourTargets) : reversed_(reversed) {
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < colourTargets; ++i)
        glClearNamedFramebufferfv(GLuint(fbo), GL_COLOR, i, zero);
    const float clearDepth = reversed ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(GLuint(fbo), GL_DEPTH, 0, &clearDepth);
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glDisable(GL_CULL_FACE);
}

SceneDrawState::~SceneDrawState() {
    if (reversed_) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

std::vector<std::pair<std::string, double>> GBufferPass::counters() const {
    std::vector<std::pair<std::string, double>> c = {
        {"draws", double(stats_.draws)},
        {"draws_culled", double(stats_.culled)},
        {"triangles", double(stats_.triangles)},
        {"triangles_culled", double(stats_.trianglesCulled)},
        {"triangles_face_culled", double(stats_.trianglesFaceCulled)},
        {"targets_written", double(written_.size())},
        {"targets_skipped", double(4 - written_.size())},
        {"motion_lod_level", double(stats_.lod)},
        {"motion_lod_draws_coarser", double(stats_.lodCoarser)},
        {"draws_occluded", double(stats_.occluded)},
        {"triangles_occluded", double(stats_.trianglesOccluded)},
        {"boxes_tested", double(stats_.boxesTested)}};
    return c;
}

} // namespace ssao
