#include "display/display_range.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssao {

bool needsFit(const ResourceDesc& d, const ViewStyle& style) {
    if (d.display == Display::Color) return false; // colours are shown as they are
    return style.fit || d.display == Display::Scalar || d.display == Display::Vector;
}

size_t fitStride(size_t pixels) { return std::max<size_t>(1, pixels / 65536); }

std::vector<FitSample> fitSamples(const Image& img, const Image* mask) {
    const size_t pixels = size_t(img.width) * size_t(img.height);
    const size_t stride = fitStride(pixels);
    std::vector<FitSample> out;
    out.reserve(pixels / stride + 1);
    for (size_t p = 0; p < pixels; p += stride) {
        const int x = int(p % size_t(img.width)), y = int(p / size_t(img.width));
        FitSample s(0.0f, 0.0f, 0.0f, 1.0f);
        for (int c = 0; c < std::min(3, img.channels); ++c)
            s[c] = img.at(x, y, c);
        if (mask) s.w = mask->at(mapPixel(x, img.width, mask->width), mapPixel(y, img.height, mask->height));
        out.push_back(s);
    }
    return out;
}

DisplayRange displayRange(const Image& img, const ResourceDesc& d, const Image* mask, const ViewStyle& style) {
    if (!needsFit(d, style)) return fitRange({}, img.channels, d, style); // the natural range
    return fitRange(fitSamples(img, mask), img.channels, d, style);
}

DisplayRange fitRange(const std::vector<FitSample>& samples, int imageChannels, const ResourceDesc& d,
                      const ViewStyle& style) {
    DisplayRange r;
    if (d.display == Display::Direction) r = {glm::vec3(-1.0f), glm::vec3(1.0f), false};
    if (d.display == Display::Signed) r = {glm::vec3(-kSignedRange), glm::vec3(kSignedRange), false};
    if (!needsFit(d, style)) return r;
    const bool vector = d.display == Display::Vector || d.display == Display::Direction;
    const int channels = vector ? std::min(3, imageChannels) : 1;
    std::vector<float> values[3];
    for (const FitSample& s : samples) {
        if (!(s.w > 0.0f)) continue; // not geometry
        for (int c = 0; c < channels; ++c) {
            const float v = s[c] * d.decodeScale + d.decodeOffset;
            if (std::isfinite(v)) values[c].push_back(v);
        }
    }
    for (int c = 0; c < channels; ++c) {
        if (values[c].empty()) return r;
        float lo = quantile(values[c], 0.01), hi = quantile(values[c], 0.99);
        if (!(hi - lo > 1e-6f * std::max(std::abs(lo), std::abs(hi)))) { // a flat image
            const float pad = std::max(std::abs(lo) * 1e-3f, 1e-6f);
            lo -= pad, hi += pad;
        }
        r.lo[c] = lo, r.hi[c] = hi;
    }
    if (!vector) r.lo = glm::vec3(r.lo.x), r.hi = glm::vec3(r.hi.x);
    if (d.display == Display::Signed) { // 0 stays in the middle (white): symmetric about it
        const float m = std::max(std::abs(r.lo.x), std::abs(r.hi.x));
        r.lo = glm::vec3(-m), r.hi = glm::vec3(m);
    }
    r.fitted = true;
    return r;
}

std::string rangeText(const DisplayRange& r, const ResourceDesc& d) {
    if (d.display == Display::Color) return "";
    char buf[200];
    const char* unit = d.unit.empty() ? "" : d.unit.c_str();
    const char* fitted = r.fitted ? " (fitted)" : "";
    if ((d.display == Display::Vector || d.display == Display::Direction) && r.fitted)
        std::snprintf(buf, sizeof buf, "x %.3g..%.3g  y %.3g..%.3g  z %.3g..%.3g %s%s", r.lo.x, r.hi.x,
                      r.lo.y, r.hi.y, r.lo.z, r.hi.z, unit, fitted);
    else
        std::snprintf(buf, sizeof buf, "%.4g .. %.4g %s%s", r.lo.x, r.hi.x, unit, fitted);
    return buf;
}

} // namespace ssao
