#include "view/frame/inspector.h"

#include "base/image.h"

#include <algorithm>

namespace ssao {

glm::ivec2 Inspector::hoverPixel(const Renderer& r, const ViewState& view) {
    if (view.hoverUv.x < 0.0f || r.width() <= 0) return {-1, -1};
    return {std::clamp(int(view.hoverUv.x * float(r.width())), 0, r.width() - 1),
            std::clamp(int(view.hoverUv.y * float(r.height())), 0, r.height() - 1)};
}

const std::optional<PixelInspection>& Inspector::inspection(Renderer& r, const ViewState& view, bool interacting,
                                                            std::string& error) {
    const Resource* ao = r.graph().find(view.cursorOnB() ? "b.ao.raw" : "ao.raw");
    const uint64_t v = ao ? ao->version : 0;
    const glm::ivec2 px = hoverPixel(r, view);
    // While the view moves the AO changes every frame: keep the last record instead of running the
    // probe (a full-shader draw and a read-back) each time.
    const bool moved = px != inspectedPixel_ || view.cursorOnB() != inspectedChain_;
    if (moved || (v != inspectedVersion_ && !interacting)) {
        try {
            inspection_ = r.inspect(view.cursorOnB(), px);
        } catch (const std::exception& e) {
            inspection_.reset();
            error = e.what();
        }
        inspectedPixel_ = px;
        inspectedChain_ = view.cursorOnB();
        inspectedVersion_ = v;
    }
    return inspection_;
}

std::vector<float> Inspector::valueAt(const Renderer& r, const std::string& buffer, glm::ivec2 pixel) {
    const Resource* res = r.graph().find(buffer);
    // A buffer the current view does not need was not computed this frame: show nothing, not stale data.
    if (!res || pixel.x < 0 || pixel.y < 0 || !r.graph().current(buffer)) return {};
    CachedValue& c = values_[buffer];
    if (c.pixel == pixel && c.version == res->version && c.generation == res->generation) return c.values;
    const int x = mapPixel(pixel.x, std::max(r.width(), 1), res->width());
    const int y = mapPixel(pixel.y, std::max(r.height(), 1), res->height());
    const glm::vec4 t = res->texture.readTexel(x, y);
    std::vector<float> out;
    for (int ch = 0; ch < std::max(1, res->desc.channels); ++ch)
        out.push_back(res->desc.display == Display::Color ? t[ch]
                                                          : t[ch] * res->desc.decodeScale + res->desc.decodeOffset);
    c = {pixel, res->version, res->generation, out};
    return out;
}

} // namespace ssao
