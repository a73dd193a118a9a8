#include "passes/position_pyramid_pass.h"

#include "gl/shader_library.h"
#include "passes/gbuffer_pass.h"

#include "../../shaders/include/bindings.h"

#include <algorithm>

namespace ssao {

void PositionPyramidPass::setup(PassBuilder& b, const Settings& s) const {
    b.read("gbuffer.position");
    ResourceDesc out = describe(kOutput, glFormat(s.gbuffer.positionFormat), 3, Display::Vector,
                                "view-space positions, MIP pyramid (one real texel of each 2x2)", "scene units");
    out.levels = kMaxLevels;
    out.internal = true; // level 0 is gbuffer.position itself: not listed again
    b.write(out);
}

void PositionPyramidPass::run(PassContext& ctx, const NoConfig&) {
    const gl::Texture2D& src = ctx.in("gbuffer.position");
    const gl::Texture2D& mips = ctx.in(kOutput);
    if (mips.id() != textureId_) { // reallocated (size, format): attach the new levels
        levels_.clear();
        for (int level = 1; level < mips.levels(); ++level)
            levels_.emplace_back(mips, level, std::string(kOutput) + ".level" + std::to_string(level));
        textureId_ = mips.id();
    }
    glCopyImageSubData(src.id(), GL_TEXTURE_2D, 0, 0, 0, 0, mips.id(), GL_TEXTURE_2D, 0, 0, 0, 0, src.width(),
                       src.height(), 1);
    glUseProgram(ctx.shaders.program("passes/fullscreen.vert", "passes/position_downsample.frag", {}));
    mips.bind(SSAO_TEX_POSITION_MIPS);
    for (int level = 1; level < mips.levels(); ++level) {
        // Only the level read is visible to the sampler, so writing the next is no feedback loop.
        glTextureParameteri(mips.id(), GL_TEXTURE_BASE_LEVEL, level - 1);
        glTextureParameteri(mips.id(), GL_TEXTURE_MAX_LEVEL, level - 1);
        levels_[size_t(level - 1)].bind();
        ctx.drawFullscreen();
    }
    glTextureParameteri(mips.id(), GL_TEXTURE_BASE_LEVEL, 0);
    glTextureParameteri(mips.id(), GL_TEXTURE_MAX_LEVEL, mips.levels() - 1);
    glBindTextureUnit(SSAO_TEX_POSITION_MIPS, 0);
}

} // namespace ssao
