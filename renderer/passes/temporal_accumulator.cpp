#include "passes/temporal_accumulator.h"

#include "gl/shader_library.h"
#include "scene/camera.h"

#include "../../shaders/include/bindings.h"

#include <glm/gtc/type_ptr.hpp>

namespace ssao {

void TemporalAccumulator::run(PassContext& ctx, const std::string& ao, const std::string& passName) {
    const glm::ivec2 size = ctx.size(ao);
    const int next = 1 - current_;
    for (auto& h : history_) {
        if (h.texture().width() != size.x || h.texture().height() != size.y) valid_ = false;
        h.ensure(size.x, size.y, GL_RGBA32F, passName + ".history");
        // Nearest: a history texel belongs to one surface; blending two would invent a third.
        glTextureParameteri(h.texture().id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(h.texture().id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    const FrameInfo& f = ctx.frame;
    const glm::mat4 view = f.camera->view();
    const glm::mat4 viewProj = f.camera->projection(float(f.width) / float(f.height)) * view;
    const bool reset = !valid_ || f.temporalReset;
    const TemporalSettings& t = ctx.settings.temporal;

    // 1: blend into the next history.
    GLuint prog = ctx.shaders.program("passes/fullscreen.vert", "passes/temporal.frag");
    glUseProgram(prog);
    glProgramUniformMatrix4fv(prog, 0, 1, GL_FALSE, glm::value_ptr(prevViewProj_));
    glProgramUniformMatrix4fv(prog, 1, 1, GL_FALSE, glm::value_ptr(prevView_));
    const glm::mat4 invView = glm::inverse(view);
    glProgramUniformMatrix4fv(prog, 2, 1, GL_FALSE, glm::value_ptr(invView));
    glProgramUniform4f(prog, 3, reset ? 1.0f : 0.0f, float(std::max(t.frames, 1)), t.depthTolerance, 0.0f);
    ctx.in(ao).bind(SSAO_TEX_AO);
    ctx.in("gbuffer.depth").bind(SSAO_TEX_LINEAR_DEPTH);
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
    valid_ = true;
}

} // namespace ssao
