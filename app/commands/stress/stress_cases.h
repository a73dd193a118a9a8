// The conditions under which SSAO breaks, as data (issue 9, `ssaolab stress`): projection (near
// and far planes), scale and placement of the whole scene, G-buffer precision, every parameter at
// the ends of its range, and awkward cameras. Each case says how it changes the scene, the camera
// and the settings, and whether the AO must equal the benign render's (invariance: scaling the
// scene and its radius together, moving it far from the origin).
#pragma once
#include "scene/camera.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct StressCase {
    std::string axis;    // "near", "far", "projection", "scale", "translate", "gbuffer", "limits", "camera", "geometry"
    std::string variant; // e.g. "1e-4", "x1000", "ao.power=16"
    double scale = 1.0;              // the scene and the camera scaled about the origin ...
    glm::dvec3 offset{0.0};          // ... then moved by this (scene units)
    bool sceneOrigin = true;         // false: float positions in file coordinates (no Scene::origin)
    float nearZ = 0.0f, farZ = 0.0f; // > 0: fixed clip planes, x the scene's diagonal (else fitted); far may be inf
    std::optional<DepthMode> depth;       // unset: the default's
    std::optional<Projection> projection; // unset: perspective
    std::function<void(Settings&)> settings;            // null: unchanged
    std::function<void(Camera&, const Scene&)> camera;  // null: the scene's view
    std::function<void(Scene&)> geometry;               // null: the scene as loaded
    bool invariant = false; // AO must match the benign render (within the stated RMSE)
    bool compared = false;  // the RMSE against the benign render is reported, not required
};

// Every case for a technique (its own rows at their limits included).
std::vector<StressCase> stressCases(const std::string& technique);

// The scene scaled about the file's origin then translated, in double; the result picks its own
// origin (Scene::setWorldPositions) as a glTF file placed there would.
Scene transformScene(const Scene& s, double scale, const glm::dvec3& offset, bool sceneOrigin = true);
// A camera of `from` (scene frame) moved alike into the frame of `to`.
Camera transformCamera(const Camera& c, const Scene& from, const Scene& to, double scale,
                       const glm::dvec3& offset);

} // namespace ssao
