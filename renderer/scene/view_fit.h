// Fitting a view to a scene: clip planes from the bounds, and an orbit target for cameras that
// come with no target (glTF cameras are a position and a direction).
#pragma once
#include "scene/scene.h"

#include <optional>

namespace ssao {

// Near and far planes that enclose the scene's bounding box as seen from `c` (view-space depth
// range of its corners, with a small margin), with far/near ≤ 1e4 so depth keeps precision.
std::pair<float, float> fitClipPlanes(const Camera& c, const Bounds& b);
// The least and greatest depth of the box's corners along the view axis (target - eye), scene units.
std::pair<float, float> depthRange(const Camera& c, const Bounds& b);
// The same through a world -> view matrix (depth = -z in view space).
std::pair<float, float> depthRange(const glm::mat4& view, const Bounds& b);
// `c` with near/far fitted when c.clip == Fit, unchanged when Fixed.
Camera effectiveCamera(const Camera& c, const Bounds& b);

// Distance along the view ray of the first triangle hit, if any (brute force: called on load).
std::optional<float> firstHit(const Scene& s, const glm::vec3& origin, const glm::vec3& dir);
// Puts c.target on the view ray at the depth of the bounds' centre (or, when the centre is
// behind the camera, at the first hit, else one scene radius ahead): the point orbit turns
// around and zoom moves towards.
void placeOrbitTarget(Camera& c, const Scene& s);

} // namespace ssao
