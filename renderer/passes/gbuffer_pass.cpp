#include "passes/gbuffer_pass.h"

#include "gl/shader_library.h"
#include "scene/gpu_scene.h"

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
    c.occluded = s.skip.occluded;
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
        if (c.skipUnused && !ctx.needed(t.name)) {
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
    stats_ = ctx.scene()->draw(programs, o);
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
