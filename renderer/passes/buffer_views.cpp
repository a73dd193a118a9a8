#include "passes/buffer_views.h"

#include "../../shaders/include/bindings.h"

#include <glm/glm.hpp>

namespace ssao {

void BufferViews::update(Renderer& r) {
    if (owner_ != &r) versions_.fill(0), owner_ = &r;
    composite_ = &r.composite().color();
    const int w = r.width(), h = r.height();
    // A scale that maps the scene's depth range into [0,1] for position/depth views.
    const Camera& cam = r.camera();
    const float extent = std::max(1e-6f, glm::length(cam.target - cam.eye) * 2.0f);
    struct Src {
        BufferId id;
        const gl::Texture2D* tex;
        const Pass* pass;
        int mode;
        float scale;
    };
    const bool unorm = r.settings().gbuffer.normalFormat == TargetFormat::RGBA8;
    const Src srcs[] = {
        {BufferId::Position, &r.gbuffer().position(), &r.gbuffer(), SSAO_VIEW_POSITION, 0.5f / extent},
        {BufferId::Normal, &r.gbuffer().normal(), &r.gbuffer(),
         unorm ? SSAO_VIEW_UNORM_NORMAL : SSAO_VIEW_SIGNED, 1.0f},
        {BufferId::Depth, &r.gbuffer().linearDepth(), &r.gbuffer(), SSAO_VIEW_SCALAR, 1.0f / extent},
        {BufferId::Albedo, &r.gbuffer().albedo(), &r.gbuffer(), SSAO_VIEW_COLOR, 1.0f},
        {BufferId::AoRaw, &r.ssao().aoRaw(), &r.ssao(), SSAO_VIEW_SCALAR, 1.0f},
        {BufferId::Ao, &r.blur().ao(), &r.blur(), SSAO_VIEW_SCALAR, 1.0f},
    };
    GLuint prog = 0;
    for (const Src& s : srcs) {
        const int i = int(s.id);
        const unsigned v = s.pass->version();
        if (versions_[size_t(i)] == v && targets_[size_t(i)].texture().width() == w) continue;
        if (!prog) {
            prog = r.shaders().program("passes/fullscreen.vert", "passes/debug_view.frag");
            glUseProgram(prog);
        }
        targets_[size_t(i)].ensure(w, h, GL_RGBA8, std::string("view.") + bufferName(s.id));
        targets_[size_t(i)].bind();
        s.tex->bind(SSAO_TEX_VIEW_SOURCE);
        r.gbuffer().position().bind(SSAO_TEX_VIEW_MASK);
        glProgramUniform1i(prog, 0, s.mode);
        glProgramUniform1f(prog, 1, s.scale);
        r.drawFullscreen();
        versions_[size_t(i)] = v;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

const gl::Texture2D& BufferViews::view(BufferId id) const {
    if (id == BufferId::Composite) return *composite_;
    return targets_[size_t(int(id))].texture();
}

} // namespace ssao
