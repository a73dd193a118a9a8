#include "display/view_painter.h"
#include "gl/readback.h"

#include "gl/shader_library.h"

#include "../../shaders/include/bindings.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ssao {

// The mapping as defines: one view.frag variant per mode (the shader says why).
static gl::Defines viewDefines(int mode, bool falseColor) {
    gl::Defines defs{{"VIEW_MODE", std::to_string(mode)}};
    if (falseColor && mode == SSAO_VIEW_SCALAR) defs.push_back({"FALSE_COLOR", "1"});
    return defs;
}

const Image& ViewPainter::maskImage(const Resource& mask) {
    if (mask.version != maskVersion_ || mask.generation != maskGeneration_ || mask_.width != mask.width()) {
        mask_ = readBack(mask.texture, 1);
        maskVersion_ = mask.version;
        maskGeneration_ = mask.generation;
    }
    return mask_;
}

DisplayRange ViewPainter::paint(const Resource& r, const Resource& mask, const ViewStyle& style,
                                gl::RenderTarget& out, gl::ShaderLibrary& shaders,
                                const gl::FullscreenTriangle& tri, const Image* raw, int maxWidth,
                                const DisplayRange* keep) {
    const ResourceDesc& d = r.desc;
    DisplayRange range;
    if (needsFit(d, style)) {
        if (keep)
            range = *keep;
        else if (raw)
            range = displayRange(*raw, d, &maskImage(mask), style);
        else // the fit's ~65k texels picked on the GPU: the same range as a read-back of all of r
            range = fitRange(picker_.pick(r.texture, mask.texture, shaders, tri), std::max(1, d.channels), d, style);
    } else {
        range = displayRange(Image{}, d, nullptr, style);
    }
    const auto [w, h] = displaySize(r.width(), r.height(), maxWidth);
    out.ensure(w, h, GL_RGBA8, "view." + d.name);
    out.bind(); // the viewport of its w x h attachment
    const int mode = d.display == Display::Color                                         ? SSAO_VIEW_COLOR
                     : (d.display == Display::Vector || d.display == Display::Direction) ? SSAO_VIEW_VECTOR
                     : d.display == Display::Signed                                      ? SSAO_VIEW_SIGNED
                                                                                         : SSAO_VIEW_SCALAR;
    const GLuint prog = shaders.program("passes/fullscreen.vert", "display/view.frag", viewDefines(mode, style.falseColor));
    glUseProgram(prog);
    glProgramUniform3f(prog, 1, range.lo.x, range.lo.y, range.lo.z);
    glProgramUniform3f(prog, 5, range.hi.x, range.hi.y, range.hi.z);
    glProgramUniform2f(prog, 3, d.decodeScale, d.decodeOffset);
    glProgramUniform1f(prog, 4, 1.0f);
    glProgramUniform1i(prog, 6, d.channels);
    r.texture.bind(SSAO_TEX_VIEW_SOURCE);
    mask.texture.bind(SSAO_TEX_VIEW_MASK);
    tri.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return range;
}

void ViewPainter::paintDifference(const Resource& a, const Resource& b, float scale, const Resource& mask,
                                  gl::RenderTarget& out, gl::ShaderLibrary& shaders,
                                  const gl::FullscreenTriangle& tri) {
    out.ensure(a.width(), a.height(), GL_RGBA8, "view.diff." + a.desc.name);
    out.bind();
    const GLuint prog = shaders.program("passes/fullscreen.vert", "display/view.frag", viewDefines(SSAO_VIEW_DIFF, false));
    glUseProgram(prog);
    glProgramUniform3f(prog, 1, 0.0f, 0.0f, 0.0f);
    glProgramUniform3f(prog, 5, 1.0f, 1.0f, 1.0f);
    glProgramUniform2f(prog, 3, a.desc.decodeScale, a.desc.decodeOffset);
    glProgramUniform1f(prog, 4, scale);
    glProgramUniform1i(prog, 6, a.desc.channels);
    a.texture.bind(SSAO_TEX_VIEW_SOURCE);
    b.texture.bind(SSAO_TEX_VIEW_SOURCE_B);
    mask.texture.bind(SSAO_TEX_VIEW_MASK);
    tri.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace ssao
