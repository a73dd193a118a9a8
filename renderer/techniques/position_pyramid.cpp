#include "techniques/position_pyramid.h"

#include "gl/shader_library.h"
#include "graph/pass.h"

#include "../../shaders/include/bindings.h"

#include <algorithm>

namespace ssao {

void PositionPyramid::build(PassContext& ctx, const gl::Texture2D& positions) {
    if (!tex_ || positions.width() != w_ || positions.height() != h_ || positions.format() != fmt_) {
        w_ = positions.width(), h_ = positions.height(), fmt_ = positions.format();
        levels_ = 1;
        while (levels_ < kMaxLevels && std::max(w_, h_) >> levels_ > 0) ++levels_;
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &id);
        tex_ = gl::TextureHandle(id);
        glTextureStorage2D(id, levels_, fmt_, w_, h_);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST); // never blend positions
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        gl::label(GL_TEXTURE, id, "ao.position_pyramid");
        fbos_.clear();
        for (int level = 1; level < levels_; ++level) {
            GLuint fb = 0;
            glCreateFramebuffers(1, &fb);
            glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, id, level);
            fbos_.emplace_back(fb);
        }
    }
    // The caller's framebuffer and viewport survive (the inspector draws into its own).
    GLint prevFbo = 0, prevViewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &prevFbo);
    glGetIntegerv(GL_VIEWPORT, prevViewport);
    glCopyImageSubData(positions.id(), GL_TEXTURE_2D, 0, 0, 0, 0, tex_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, w_, h_, 1);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/position_downsample.frag", {}));
    glBindTextureUnit(SSAO_TEX_POSITION_MIPS, tex_.id());
    for (int level = 1; level < levels_; ++level) {
        // Only the level read is visible to the sampler, so writing the next is no feedback loop.
        glTextureParameteri(tex_.id(), GL_TEXTURE_BASE_LEVEL, level - 1);
        glTextureParameteri(tex_.id(), GL_TEXTURE_MAX_LEVEL, level - 1);
        glBindFramebuffer(GL_FRAMEBUFFER, fbos_[size_t(level - 1)].id());
        glViewport(0, 0, std::max(w_ >> level, 1), std::max(h_ >> level, 1));
        ctx.drawFullscreen();
    }
    glTextureParameteri(tex_.id(), GL_TEXTURE_BASE_LEVEL, 0);
    glTextureParameteri(tex_.id(), GL_TEXTURE_MAX_LEVEL, levels_ - 1);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(prevFbo));
    glViewport(prevViewport[0], prevViewport[1], prevViewport[2], prevViewport[3]);
}

} // namespace ssao
