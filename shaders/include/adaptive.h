// Adaptive sample counts (ao.adaptive, ASSAO/CACAO-style), written once for C++ and GLSL: the
// shaders take this many steps or taps, and metrics.json's sample share (output/skip_report) counts
// with the very same function. A march takes one step per `pxPerSample` pixels of radius, an area
// sampler one tap per pxPerSample^2 pixels of the disc; never below 2 steps / 4 taps nor above the
// technique's full count. pxPerSample 0 = off (the full count).
// In GLSL the loader inlines this file; C++ includes it (namespace ssao::gpu).
#ifndef SSAOLAB_ADAPTIVE_H
#define SSAOLAB_ADAPTIVE_H
#ifdef __cplusplus
#include <algorithm>
#include <cmath>
namespace ssao::gpu {
inline int clamp(int v, int lo, int hi) { return std::min(std::max(v, lo), hi); }
using std::ceil;
using std::min;
#define SSAO_FN inline
#else
#define SSAO_FN
#endif

SSAO_FN int adaptiveSteps(float pxPerSample, int steps, float radiusPx) {
    return pxPerSample > 0.0 ? clamp(int(ceil(radiusPx / pxPerSample)), min(steps, 2), steps) : steps;
}
SSAO_FN int adaptiveSamples(float pxPerSample, int samples, float radiusPx) {
    return pxPerSample > 0.0
               ? clamp(int(ceil(3.14159265 * radiusPx * radiusPx / (pxPerSample * pxPerSample))), min(samples, 4),
                       samples)
               : samples;
}

#undef SSAO_FN
#ifdef __cplusplus
} // namespace ssao::gpu
#endif
#endif
