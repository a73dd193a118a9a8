// A named GPU buffer of the frame graph ("gbuffer.depth", "ao.raw", "composite"): its format,
// its size relative to the graph's base size, and how to show it. Everything that lists buffers
// (the app's grid and inspector, EXR/PNG output, metrics.json) enumerates these.
#pragma once
#include "gl/resources.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace ssao {

// How a buffer maps to a displayable image (display/display_range.h).
enum class Display {
    Color,     // rgb shown as is (albedo, composite)
    Unit,      // one scalar with a physical range [0,1] (AO)
    Scalar,    // one scalar with no natural range (depth): range auto-fitted over geometry
    Direction, // unit vectors, natural range [-1,1] per channel (normals)
    Vector,    // vectors with no natural range (positions): one range auto-fitted over xyz
    Signed,    // one signed scalar centred on 0 (an error): a symmetric range, diverging colours
};

struct ResourceDesc {
    std::string name;
    GLenum format = GL_R32F;
    int channels = 1;   // channels that carry data (readback, EXR, inspector)
    float scale = 1.0f; // size relative to the graph's base size (AO at half resolution: 0.5)
    Display display = Display::Unit;
    std::string unit;      // of the values, e.g. "scene units"
    std::string help;      // one line for tooltips and the README
    bool internal = false; // scratch data (ping-pong): not listed, written or reported
    int levels = 1;        // > 1: a MIP chain of at most this many levels (fewer when the size runs out)
    int margin = 0;        // pixels added beyond each edge of the scaled size (a guard band)
    int maxWidth = 0;      // > 0: at most this wide, the aspect kept as a view does (displaySize)
    // Stored value → meaning: value * decodeScale + decodeOffset ((n+1)/2 normals: 2, -1).
    float decodeScale = 1.0f, decodeOffset = 0.0f;
};

// A description in one line: name, format, data channels, display kind, unit and help.
inline ResourceDesc describe(std::string name, GLenum format, int channels, Display display, std::string help,
                             std::string unit = "") {
    ResourceDesc d;
    d.name = std::move(name), d.format = format, d.channels = channels, d.display = display;
    d.help = std::move(help), d.unit = std::move(unit);
    return d;
}

// Size of a resource of scale `scale` in a graph of base size w x h (rounded up, at least 1).
int scaledSize(int base, float scale);
// An image w x h shown at most `maxWidth` wide (0: as it is): maxWidth x round(h maxWidth / w).
// The grid's cells are painted at this size (display/view_painter.cpp), and a resource with
// ResourceDesc::maxWidth is allocated at it, so such a cell shows it texel for texel.
inline std::pair<int, int> displaySize(int w, int h, int maxWidth) {
    if (maxWidth <= 0 || maxWidth >= w) return {w, h};
    return {maxWidth, std::max(1, int(std::lround(double(h) * maxWidth / w)))};
}

struct Resource {
    ResourceDesc desc;
    gl::Texture2D texture;
    std::string producer;    // pass that writes it
    uint64_t version = 0;    // changes every time the producer runs (never reused)
    unsigned generation = 0; // changes when the texture is reallocated
    int width() const { return texture.width(); }
    int height() const { return texture.height(); }
};

bool isDepthFormat(GLenum format);

} // namespace ssao
