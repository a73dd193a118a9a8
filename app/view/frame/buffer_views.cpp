#include "view/frame/buffer_views.h"

#include <algorithm>
#include <cstdio>

namespace ssao {

void BufferViews::update(Renderer& r, const ViewStyle& style, const std::vector<std::string>& names, int maxWidth,
                         bool keepRanges) {
    const Resource& mask = r.resource("gbuffer.depth");
    shown_ = names;
    for (const auto& name : names) {
        const Resource* res = r.graph().find(name);
        if (!res) continue;
        View& v = views_[name];
        const int width = maxWidth > 0 ? std::min(maxWidth, res->width()) : res->width();
        const bool current = v.target.texture() && v.version == res->version && v.generation == res->generation &&
                             v.style == style && v.target.texture().width() == width;
        const bool owedFit = v.refit && !keepRanges;
        if (current && !owedFit) continue;
        // A kept range while moving; in a still frame too, when the buffer changed, with its fit
        // owed to the next call (each fit is a pick pass and a read-back: the grid's three fits,
        // position, depth and z-buffer, are spread over frames).
        const bool keep = v.range.fitted && v.style == style && v.target.texture() && !(current && owedFit);
        v.range = painter_.paint(*res, mask, style, v.target, r.shaders(), r.triangle(), nullptr, width,
                                 keep ? &v.range : nullptr);
        v.refit = keep && needsFit(res->desc, style);
        v.version = res->version;
        v.generation = res->generation;
        v.style = style;
        const std::string range = rangeText(v.range, res->desc);
        v.label = name + (range.empty() ? "" : "  " + range);
        if (res->desc.scale != 1.0f) {
            char buf[48];
            std::snprintf(buf, sizeof buf, "  (%dx%d)", res->width(), res->height());
            v.label += buf;
        }
    }
}

bool BufferViews::fitsPending() const {
    for (const auto& name : shown_) { // a view off screen is fitted when it is shown again
        auto it = views_.find(name);
        if (it != views_.end() && it->second.refit) return true;
    }
    return false;
}

void BufferViews::forgetRanges() {
    for (auto& [name, v] : views_) v.range.fitted = false, v.refit = false;
}

const BufferViews::View& BufferViews::difference(Renderer& r, const std::string& a, const std::string& b,
                                                 float scale) {
    const Resource& ra = r.resource(a);
    const Resource& rb = r.resource(b);
    char key[160];
    std::snprintf(key, sizeof key, "%s@%llu/%u|%s@%llu/%u|%g", a.c_str(), (unsigned long long)ra.version,
                  ra.generation, b.c_str(), (unsigned long long)rb.version, rb.generation, scale);
    if (diffKey_ != key || !diff_.target.texture()) {
        painter_.paintDifference(ra, rb, scale, r.resource("gbuffer.depth"), diff_.target, r.shaders(),
                                 r.triangle());
        char label[96];
        std::snprintf(label, sizeof label, "A - B (x%g): red A brighter, blue B brighter", scale);
        diff_.label = label;
        diffKey_ = key;
    }
    return diff_;
}

const BufferViews::View* BufferViews::find(const std::string& name) const {
    auto it = views_.find(name);
    return it == views_.end() ? nullptr : &it->second;
}

} // namespace ssao
