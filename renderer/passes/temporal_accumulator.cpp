#include "passes/temporal_accumulator.h"

#include "gl/shader_library.h"
#include "techniques/technique.h"

#include "../../shaders/include/bindings.h"

#include <glm/gtc/type_ptr.hpp>

namespace ssao {

TemporalConfig temporalConfig(const Settings& s, const FrameInfo& f) {
    TemporalConfig c{};
    if (!s.temporal.enabled) return c;
    c.frame = f.constants;
    c.enabled = 1;
    c.reset = f.temporalReset;
    c.frames = float(s.temporal.frames);
    c.planeTolerance = s.temporal.planeTolerance;
    c.movingFrames = float(s.temporal.movingFrames);
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    c.staticNoise = t.staticNoise && t.staticNoise(s);
    c.normalUnorm = s.gbuffer.normalFormat == TargetFormat::RGBA8;
    return c;
}

void TemporalAccumulator::run(PassContext& ctx, const TemporalConfig& c, const std::string& ao,
                              const std::string& passName) {
    const glm::ivec2 size = ctx.size(ao);
    const int next = 1 - current_;
    for (auto& h : history_) {
        if (h.texture().width() != size.x || h.texture().height() != size.y) valid_ = false;
        h.ensure(size.x, size.y, GL_RGBA32F, passName + ".history");
        // Nearest: a history texel belongs to one surface; blending two would invent a third.
        glTextureParameteri(h.texture().id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(h.texture().id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    const glm::mat4 view = c.frame.view;
    const glm::mat4 viewProj = c.frame.proj * view;
    const bool reset = !valid_ || c.reset;

    // 1: blend into the next history.
    gl::Defines defs;
    if (c.normalUnorm) defs.push_back({"NORMAL_UNORM", "1"});
    GLuint prog = ctx.shaders.program("passes/fullscreen.vert", "passes/temporal.frag", defs);
    glUseProgram(prog);
    glProgramUniformMatrix4fv(prog, 0, 1, GL_FALSE, glm::value_ptr(prevViewProj_));
    glProgramUniformMatrix4fv(prog, 1, 1, GL_FALSE, glm::value_ptr(prevView_));
    const glm::mat4 invView = glm::inverse(view);
    glProgramUniformMatrix4fv(prog, 2, 1, GL_FALSE, glm::value_ptr(invView));
    glProgramUniform4f(prog, 3, reset ? 1.0f : 0.0f, c.frames, c.planeTolerance, c.staticNoise ? 1.0f : 0.0f);
    glProgramUniform4fv(prog, 4, 1, glm::value_ptr(prevLens_));
    glProgramUniform1f(prog, 5, c.movingFrames);
    ctx.in(ao).bind(SSAO_TEX_AO);
    ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
    ctx.in("gbuffer.normal").bind(SSAO_TEX_NORMAL);
    history_[current_].texture().bind(SSAO_TEX_HISTORY);
    history_[next].bind();
    ctx.drawFullscreen();

    // 2: the accumulated AO back into the graph's AO target.
    GLuint resolve =
        ctx.shaders.program("passes/fullscreen.vert", "passes/temporal.frag", {{"RESOLVE", "1"}});
    glUseProgram(resolve);
    history_[next].texture().bind(SSAO_TEX_HISTORY);
    ctx.bindOutputs({ao});
    ctx.drawFullscreen();
    glBindTextureUnit(SSAO_TEX_HISTORY, 0);

    current_ = next;
    prevViewProj_ = viewProj;
    prevView_ = view;
    prevLens_ = {c.frame.invProj[0][0], c.frame.invProj[1][1], c.frame.camera.x, 0.0f};
    valid_ = true;
}

} // namespace ssao
