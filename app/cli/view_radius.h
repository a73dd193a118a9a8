// The view-radius check of `render` and the explorer (metrics/radius_check.h) for the commands whose
// R is --radius-scene x the scene's diagonal (bench, tune, tune --engine): each view's reference
// depth says what the view spans; a radius past kViewRadiusLimit of it is named once per scene,
// with the --radius-scene that gives the view kViewRadiusTarget of its extent.
#pragma once
#include "reference/reference_ao.h"
#include "scene/camera.h"

#include <string>
#include <vector>

namespace ssao {

class SceneRadiusWarnings {
  public:
    // One view of `scene`: its reference (depth), camera and R as a fraction of `diagonal`.
    void check(const std::string& scene, const std::string& view, const ReferenceImage& ref, const Camera& camera,
               double radiusScene, double diagonal);
    // "" when no view of the scene was overreached; else one line (no "ssaolab: warning:" prefix).
    // The most overreached view names it; the suggested fraction is the smallest view's.
    std::string line(const std::string& scene) const;
    // Every scene's line, in the order first checked.
    std::vector<std::string> lines() const;

  private:
    struct Worst {
        std::string scene, view;
        double share = 0, suggested = 0, radius = 0, extent = 0; // radius / extent; the --radius-scene for the view
        int views = 0, over = 0;
    };
    std::vector<Worst> scenes_;
};

} // namespace ssao
