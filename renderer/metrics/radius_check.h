// Whether the scene-mode AO radius (a fraction of the scene's bounding diagonal) is far larger
// than what the view shows: a close-up of a large scene (a street of a city, at its own first
// camera) gets a radius wider than the frame, and the AO turns dark and blotchy with nothing to
// say why. Compared with the view's extent at its median depth; the hint names a world radius
// that spans what the scene mode's default spans of a framed scene. Pure CPU code.
#pragma once
#include "scene/camera.h"
#include "settings/settings.h"

#include <cstddef>
#include <string>

namespace ssao {

// A scene radius past this fraction of the view's extent is named: its disc then spans more than
// the frame. The shared scenes at their own cameras are at 0.04-0.09, the built-in views at 0.12
// (showcase) to 0.53 (plane); walking in on the showcase's sphere the error grows with it and levels
// off past 0.6-0.8 (RMSE 0.04 at 0.12, 0.07 at 0.32, 0.11 at 0.53, 0.16 at 0.76, 0.18 at 1.2).
constexpr double kViewRadiusLimit = 0.6;
// The suggested world radius: this fraction of the view's extent (the scene mode's 5 % of the diagonal).
constexpr double kViewRadiusTarget = 0.05;

struct ViewRadiusCheck {
    bool tooLarge = false;  // scene mode, and the radius past kViewRadiusLimit x viewExtent
    double radius = 0;      // the world radius the scene mode gives, scene units
    double diagonal = 0;    // the scene's bounding-box diagonal
    double medianDepth = 0; // linear view depth, median over geometry pixels (0: none in view)
    double viewExtent = 0;  // the view's shorter side at that depth, scene units (0: unknown)
    double suggested = 0;   // kViewRadiusTarget x viewExtent, rounded to 3 significant digits
    // One line: the radius, the view's extent and `--set ao.radius=X` ("" unless tooLarge).
    std::string message() const;
};

// `depth`: `count` linear view depths (scene units; 0 or not finite = sky), any subset of the
// frame's pixels; `aspect` = width / height of the frame.
ViewRadiusCheck checkViewRadius(const float* depth, size_t count, const Camera& camera, double aspect,
                                const AoSettings& ao, double sceneDiagonal);

} // namespace ssao
