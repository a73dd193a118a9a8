#include "cli/view_radius.h"

#include "metrics/radius_check.h"

#include <algorithm>
#include <cstdio>

namespace ssao {

void SceneRadiusWarnings::check(const std::string& scene, const std::string& view, const ReferenceImage& ref,
                                const Camera& camera, double radiusScene, double diagonal) {
    auto it = std::find_if(scenes_.begin(), scenes_.end(), [&](const Worst& w) { return w.scene == scene; });
    if (it == scenes_.end()) it = scenes_.insert(scenes_.end(), Worst{scene, "", 0, 0, 0, 0, 0, 0});
    ++it->views;
    AoSettings ao;
    ao.radiusMode = RadiusMode::Scene;
    ao.radiusScene = float(radiusScene);
    const ViewRadiusCheck c = checkViewRadius(ref.depth.data(), ref.depth.size(), camera,
                                              ref.height > 0 ? double(ref.width) / ref.height : 0.0, ao, diagonal);
    if (!c.tooLarge || !(diagonal > 0)) return;
    ++it->over;
    const double share = c.radius / c.viewExtent, fraction = c.suggested / diagonal;
    if (share > it->share) it->share = share, it->view = view, it->radius = c.radius, it->extent = c.viewExtent;
    it->suggested = it->suggested > 0 ? std::min(it->suggested, fraction) : fraction;
}

std::string SceneRadiusWarnings::line(const std::string& scene) const {
    for (const Worst& w : scenes_) {
        if (w.scene != scene || w.over == 0) continue;
        char b[520];
        std::snprintf(b, sizeof b,
                      "%s: R = %.4g units (--radius-scene of its diagonal) is %.0f%% of what view '%s' spans (%.4g units "
                      "across at its median depth; %d of %d views past %.0f%%): it reaches past the frame, where no "
                      "screen-space AO sees; --radius-scene %.3g gives the view %.0f%% of its extent",
                      scene.c_str(), w.radius, 100.0 * w.share, w.view.c_str(), w.extent, w.over, w.views,
                      100.0 * kViewRadiusLimit, w.suggested, 100.0 * kViewRadiusTarget);
        return b;
    }
    return "";
}

std::vector<std::string> SceneRadiusWarnings::lines() const {
    std::vector<std::string> out;
    for (const Worst& w : scenes_)
        if (const std::string l = line(w.scene); !l.empty()) out.push_back(l);
    return out;
}

} // namespace ssao
