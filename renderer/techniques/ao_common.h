// Settings → the AoCommon block every technique's constants start with (bindings.h), and the
// radius arithmetic the UI and reports show. Pure functions, tested without a GPU.
#pragma once
#include "techniques/technique_settings.h"

#include "../../shaders/include/bindings.h"

#include <glm/glm.hpp>

namespace ssao {

// The AO radius as it is at the centre of the view (the panel and metrics.json show it).
struct RadiusInfo {
    float sceneDiagonal = 0; // scene units
    float depth = 0;         // view depth at the centre pixel (or of the orbit target over sky)
    float world = 0;         // radius in scene units there
    float pixels = 0;        // radius in G-buffer pixels there
};

// The first step of a march lands at least this far from the pixel, in pixels (XeGTAO's minS; HBAO's
// "first step >= 1 px"): sampling the pixel itself gives a zero delta and self-occlusion lines.
constexpr float kMinFirstStepPx = 1.3f;

// Scene units covered by one pixel at unit view depth, for a G-buffer `heightPx` tall (an
// orthographic projection: at every depth). `depth` below is the pixel's view distance under
// perspective and 1 under orthographic projection (shaders: frameDepthScale).
float unitsPerPixelAtUnitDepth(const glm::mat4& proj, int heightPx);
// Size factor of an AO resolution (full 1, half 0.5, quarter 0.25).
float resolutionScale(AoResolution r);

// World radius at a pixel `depth` scene units away (screen mode depends on depth; the others not).
float worldRadius(const AoSettings& s, float sceneDiagonal, float depth, float unitsPerPixel);
// The radius in pixels of the G-buffer at view depth `depth`.
float radiusInPixels(const AoSettings& s, float sceneDiagonal, float depth, float unitsPerPixel);

// skipSky: SkipSettings::sky (flags.x; a uniform, not a shader variant, so geometry pixels run the
// very same code either way and the skip stays bit-exact). normalUnorm: the G-buffer stores normals
// as (n+1)/2 (flags.z). The noise kind and the pyramid offset (estimator.y, .w) are the technique's.
gpu::AoCommon packAoCommon(const AoSettings& s, float sceneDiagonal, float unitsPerPixel, glm::ivec2 target,
                           bool skipSky = true, bool normalUnorm = false);

} // namespace ssao
