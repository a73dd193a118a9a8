#include "metrics/radius_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ssao {

namespace {
double roundTo3(double v) {
    if (!(v > 0.0)) return v;
    const double scale = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    return std::round(v / scale) * scale;
}
} // namespace

ViewRadiusCheck checkViewRadius(const float* depth, size_t count, const Camera& camera, double aspect,
                                const AoSettings& ao, double sceneDiagonal) {
    ViewRadiusCheck c;
    c.diagonal = sceneDiagonal;
    c.radius = double(ao.radiusScene) * sceneDiagonal;
    std::vector<float> d;
    d.reserve(count);
    for (size_t i = 0; i < count; ++i)
        if (depth[i] > 0.0f && std::isfinite(depth[i])) d.push_back(depth[i]);
    if (d.empty() || !(aspect > 0.0)) return c;
    std::nth_element(d.begin(), d.begin() + long(d.size() / 2), d.end());
    c.medianDepth = d[d.size() / 2];
    // Orthographic: the same height at every depth.
    const double height = camera.orthographic()
                              ? 2.0 * double(camera.orthoHalfHeight())
                              : 2.0 * c.medianDepth * std::tan(double(camera.fovYDeg) * M_PI / 360.0);
    c.viewExtent = height * std::min(1.0, aspect);
    c.suggested = roundTo3(kViewRadiusTarget * c.viewExtent);
    c.tooLarge = ao.radiusMode == RadiusMode::Scene && c.viewExtent > 0.0 &&
                 c.radius > kViewRadiusLimit * c.viewExtent;
    return c;
}

std::string ViewRadiusCheck::message() const {
    if (!tooLarge) return "";
    char b[480];
    std::snprintf(b, sizeof b,
                  "the AO radius %.4g units (ao.radius_mode=scene: %.0f%% of the scene's diagonal %.4g) is %.0f%% "
                  "of what this view spans (%.4g units across at its median depth %.4g): it reaches past the frame, "
                  "where no screen-space AO sees; --set ao.radius=%.3g (world units) matches %.0f%% of the view",
                  radius, 100.0 * radius / diagonal, diagonal, 100.0 * radius / viewExtent, viewExtent, medianDepth,
                  suggested, 100.0 * kViewRadiusTarget);
    return b;
}

} // namespace ssao
