#include "techniques/ao_common.h"

#include <algorithm>
#include <cmath>

namespace ssao {

float unitsPerPixelAtUnitDepth(const glm::mat4& proj, int heightPx) {
    // proj[1][1] = cot(fovY / 2): the view at unit depth spans 2 / proj[1][1] units vertically.
    return 2.0f / (proj[1][1] * float(std::max(heightPx, 1)));
}

float resolutionScale(AoResolution r) {
    return r == AoResolution::Half ? 0.5f : r == AoResolution::Quarter ? 0.25f : 1.0f;
}

float worldRadius(const AoSettings& s, float sceneDiagonal, float depth, float unitsPerPixel) {
    switch (s.radiusMode) {
    case RadiusMode::World:
        return s.radius;
    case RadiusMode::Scene:
        return s.radiusScene * sceneDiagonal;
    case RadiusMode::Screen:
        return s.radiusPx * unitsPerPixel * depth;
    }
    return s.radius;
}

float radiusInPixels(const AoSettings& s, float sceneDiagonal, float depth, float unitsPerPixel) {
    const float perPixel = unitsPerPixel * std::max(depth, 1e-30f);
    return worldRadius(s, sceneDiagonal, depth, unitsPerPixel) / perPixel;
}

gpu::AoCommon packAoCommon(const AoSettings& s, float sceneDiagonal, float unitsPerPixel, glm::ivec2 target,
                           bool skipSky, bool normalUnorm) {
    gpu::AoCommon c{};
    const bool screen = s.radiusMode == RadiusMode::Screen;
    c.radius = {screen ? 0.0f : worldRadius(s, sceneDiagonal, 1.0f, unitsPerPixel), unitsPerPixel,
                float(screen ? SSAO_RADIUS_SCREEN : SSAO_RADIUS_WORLD), s.radiusPx};
    c.estimator = {s.power, float(SSAO_NOISE_NONE), float(int(s.normals)), 0.0f}; // noise, pyramid: the technique
    c.target = {float(target.x), float(target.y), 1.0f / float(target.x), 1.0f / float(target.y)};
    c.flags = {skipSky ? 1.0f : 0.0f, s.adaptive ? s.adaptivePx : 0.0f, normalUnorm ? 1.0f : 0.0f, 0.0f};
    return c;
}

} // namespace ssao
