// The one display mapping of ssaolab: how a buffer's values become grey levels (or colours), for
// the app's views and the PNG previews alike. Buffers with a physical range (AO in [0,1], unit
// normals in [-1,1], colours) use it; the others (depth, positions) — or any buffer when asked —
// get a range fitted over geometry pixels with robust percentiles (1st and 99th), so one far
// pixel or the sky cannot wash the view out. Vectors get one range per channel.
#pragma once
#include "base/image.h"
#include "graph/resource.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace ssao {

struct ViewStyle {
    bool fit = false;        // fit the range of every buffer, not only those without a natural one
    bool falseColor = false; // scalar buffers through a perceptual colour map instead of grey
    bool operator==(const ViewStyle& o) const { return fit == o.fit && falseColor == o.falseColor; }
};

// The natural range of a Signed buffer, ±: an AO error of a quarter saturates, as in the CLI's
// error.png heat map (metrics/evaluate.h errorHeatmap).
constexpr float kSignedRange = 0.25f;

struct DisplayRange {
    glm::vec3 lo{0.0f}, hi{1.0f}; // per channel; scalars use x
    bool fitted = false;
};

// The range to show `img` (raw texel values, decoded with the desc's decodeScale/Offset) with:
// natural when the kind has one and !style.fit, else [p1, p99] of the decoded data channels over
// pixels where `mask` (any resolution; channel 0 > 0) marks geometry.
DisplayRange displayRange(const Image& img, const ResourceDesc& d, const Image* mask, const ViewStyle& style);
// The pixels a fit reads: every fitStride(w h)-th pixel of the image in row-major order from the
// top row, at most ~65k of them (a strided subset keeps the fit cheap).
size_t fitStride(size_t pixels);
// One pixel a fit reads: its raw texel (channels x, y, z, undecoded) and, in w, the mask's value
// at that pixel (1 without a mask).
using FitSample = glm::vec4;
// The samples of `img` at the pixels above, in that order. The GPU picks the same texels itself
// (display/fit_samples.h), so the app reads back ~65k texels instead of the whole buffer.
std::vector<FitSample> fitSamples(const Image& img, const Image* mask);
// displayRange() over samples: the same result for the same samples.
DisplayRange fitRange(const std::vector<FitSample>& samples, int imageChannels, const ResourceDesc& d,
                      const ViewStyle& style);
// Whether displayRange() needs the buffer's pixels (false: the natural range is used).
bool needsFit(const ResourceDesc& d, const ViewStyle& style);
// "0.25 .. 7.9 scene units (fitted)" (vectors: one range per channel) — printed on the view.
std::string rangeText(const DisplayRange& r, const ResourceDesc& d);

} // namespace ssao
