#include "display/capture.h"

#include "display/view_painter.h"
#include "gl/readback.h"

#include <algorithm>

namespace ssao {

namespace {
const char* formatName(GLenum f) {
    switch (f) {
    case GL_R32F:
        return "r32f";
    case GL_RGBA32F:
        return "rgba32f";
    case GL_RGBA16F:
        return "rgba16f";
    case GL_RGBA8:
        return "rgba8";
    case GL_DEPTH_COMPONENT32F:
        return "depth32f";
    default:
        return "other";
    }
}
} // namespace

FrameCapture captureFrame(Renderer& r, const ViewStyle& style, bool previews) {
    FrameCapture c;
    c.settings = r.settings();
    c.camera = r.camera();
    c.width = r.width(), c.height = r.height();
    c.sceneRadius = r.sceneRadius();
    c.radius = r.radiusAtCentre();
    c.passOrder = r.graph().passOrder();
    if (const Pass* g = r.graph().pass("gbuffer")) c.gbufferCounters = g->counters();
    const Resource& mask = r.resource("gbuffer.depth");
    ViewPainter painter;
    gl::RenderTarget view;
    for (const Resource* res : r.buffers()) {
        const ResourceDesc& d = res->desc;
        CapturedBuffer b;
        b.name = d.name, b.format = formatName(d.format), b.help = d.help, b.unit = d.unit;
        b.channels = std::max(1, d.channels), b.width = res->width(), b.height = res->height();
        b.scale = d.scale;
        b.floatData = d.format != GL_RGBA8; // float data keeps NaN/inf and full precision
        b.grey = (d.display == Display::Unit || d.display == Display::Scalar) && !style.falseColor;
        const Image raw = readBack(res->texture, b.channels); // each buffer read back once
        b.values = raw;
        if (d.decodeScale != 1.0f || d.decodeOffset != 0.0f)
            for (auto& v : b.values.data)
                v = v * d.decodeScale + d.decodeOffset;
        if (previews) {
            const DisplayRange range = painter.paint(*res, mask, style, view, r.shaders(), r.triangle(), &raw);
            b.preview = readBack(view.texture(), b.grey ? 1 : 3);
            b.rangeLo = range.lo, b.rangeHi = range.hi, b.rangeFitted = range.fitted;
        }
        c.buffers.push_back(std::move(b));
    }
    return c;
}

} // namespace ssao
