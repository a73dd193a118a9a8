// The MASK alpha test, texel for texel the same on the CPU (the reference's Embree filter) and in
// shaders/include/alpha_mask.glsl (the G-buffer and the other scene passes): nearest texel, no MIP
// maps, the sampler's wrap modes. Nearest is what makes the two agree exactly; a linear filter
// would move the cut's boundary by under a texel.
#pragma once
#include "scene/scene.h"

#include <cmath>

namespace ssao {

// The texel index along one axis of n texels for the coordinate t (glTF: 0 at the first texel's
// outer edge, 1 at the last's), as GL wraps it (GL 4.5 §8.14.2: repeat, clamp to edge, mirrored
// repeat).
inline int wrapTexel(float t, int n, Wrap mode) {
    const float f = std::floor(t * float(n));
    // Far outside [0, 1] (a UV of 1e30): any texel is as good as another; keep the int in range.
    const int i = std::fabs(f) < 1e9f ? int(f) : 0;
    switch (mode) {
    case Wrap::Clamp:
        return i < 0 ? 0 : (i >= n ? n - 1 : i);
    case Wrap::Mirror: {
        const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
        return m < n ? m : 2 * n - 1 - m;
    }
    case Wrap::Repeat:
    default:
        return ((i % n) + n) % n;
    }
}

// The alpha at `uv` in [0, 1]: the texel's byte / 255.
inline float alphaAt(const AlphaTexture& t, glm::vec2 uv) {
    const int x = wrapTexel(uv.x, t.width, t.wrapS), y = wrapTexel(uv.y, t.height, t.wrapT);
    return float(t.alpha[size_t(y) * size_t(t.width) + size_t(x)]) * (1.0f / 255.0f);
}

// True where a MASK draw has no surface: factor alpha x texture alpha below the cutoff (glTF 2.0
// §3.9.4: "rendered fully opaque if greater than or equal to the cutoff, fully transparent otherwise").
inline bool cutOut(const Scene& s, const Draw& d, glm::vec2 uv) {
    if (!d.mask) return false;
    float a = d.baseColor.w;
    if (d.alphaTexture >= 0) a *= alphaAt(s.alphaTextures[size_t(d.alphaTexture)], uv);
    return a < d.alphaCutoff;
}

} // namespace ssao
