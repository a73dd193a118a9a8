#include "display/display_range.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssao {

float quantile(std::vector<float>& v, double q) {
    if (v.empty()) return NAN;
    const size_t k = size_t(std::clamp(q, 0.0, 1.0) * double(v.size() - 1) + 0.5);
    std::nth_element(v.begin(), v.begin() + ptrdiff_t(k), v.end());
    return v[k];
}

bool needsFit(const ResourceDesc& d, const ViewStyle& style) {
    if (d.display == Display::Color) return false; // colours are shown as they are
    return style.fit || d.display == Display::Scalar || d.display == Display::Vector;
}

DisplayRange displayRange(const Image& img, const ResourceDesc& d, const Image* mask, const ViewStyle& style) {
    DisplayRange r;
    if (d.display == Display::Direction) r = {-1.0f, 1.0f, false};
    if (!needsFit(d, style)) return r;
    const int channels = (d.display == Display::Vector || d.display == Display::Direction) ? std::min(3, img.channels) : 1;
    // At most ~65k pixels: a strided subset keeps the fit cheap and the result the same for the
    // app and the PNG (both call this on the same read-back image).
    const size_t pixels = size_t(img.width) * size_t(img.height);
    const size_t stride = std::max<size_t>(1, pixels / 65536);
    std::vector<float> values;
    values.reserve(pixels / stride * size_t(channels) + 1);
    for (size_t p = 0; p < pixels; p += stride) {
        const int x = int(p % size_t(img.width)), y = int(p / size_t(img.width));
        if (mask) {
            const int mx = std::min(mask->width - 1, x * mask->width / img.width);
            const int my = std::min(mask->height - 1, y * mask->height / img.height);
            if (!(mask->at(mx, my) > 0.0f)) continue;
        }
        for (int c = 0; c < channels; ++c) {
            const float v = img.at(x, y, c) * d.decodeScale + d.decodeOffset;
            if (std::isfinite(v)) values.push_back(v);
        }
    }
    if (values.empty()) return r;
    r.lo = quantile(values, 0.01);
    r.hi = quantile(values, 0.99);
    r.fitted = true;
    if (!(r.hi - r.lo > 1e-6f * std::max(std::abs(r.lo), std::abs(r.hi)))) { // a flat image
        const float pad = std::max(std::abs(r.lo) * 1e-3f, 1e-6f);
        r.lo -= pad, r.hi += pad;
    }
    return r;
}

std::string rangeText(const DisplayRange& r, const ResourceDesc& d) {
    if (d.display == Display::Color) return "";
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.4g .. %.4g%s%s%s", r.lo, r.hi, d.unit.empty() ? "" : " ", d.unit.c_str(),
                  r.fitted ? " (fitted)" : "");
    return buf;
}

} // namespace ssao
