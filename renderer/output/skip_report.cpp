#include "output/skip_report.h"

#include "base/image.h"
#include "settings/params.h"
#include "techniques/ao_common.h"
#include "techniques/technique.h"

#include <algorithm>
#include <cmath>

namespace ssao {

nlohmann::json skipCounters(const FrameCapture& c, const FrameReport& frame) {
    nlohmann::json j;
    std::vector<std::string> ran, clean, culled;
    for (const auto& p : frame.passes)
        (p.ran ? ran : p.culled ? culled : clean).push_back(p.name);
    j["passes"] = {{"ran", ran}, {"clean", clean}, {"culled", culled}};
    const Settings& s = c.settings;
    j["settings"] = {{"sky", s.skip.sky}, {"cull", s.skip.cull}, {"unused_targets", s.skip.unusedTargets},
                     {"hidden_faces", s.skip.hiddenFaces}, {"occluded", s.skip.occluded},
                     {"adaptive", s.ao.adaptive}};
    if (!c.gbufferCounters.empty()) {
        nlohmann::json gb = nlohmann::json::object();
        for (const auto& [k, v] : c.gbufferCounters)
            gb[k] = v == std::floor(v) ? nlohmann::json(int64_t(v)) : nlohmann::json(v);
        j["gbuffer"] = gb;
    }
    // Sky and adaptive: from the linear depth (0 = sky), at the G-buffer's resolution.
    const Image& depth = c.get("gbuffer.depth").values;
    const Camera& cam = c.camera;
    const glm::mat4 proj = cam.projection(float(c.width) / float(std::max(c.height, 1)));
    const float upp = unitsPerPixelAtUnitDepth(proj, c.height);
    const float diag = 2.0f * c.sceneRadius;
    size_t sky = 0, geo = 0;
    double share = 0.0;
    for (float z : depth.data) {
        if (!(z > 0.0f)) {
            ++sky;
            continue;
        }
        ++geo;
        const float depthScale = cam.orthographic() ? 1.0f : z;
        share += adaptiveShare(s, radiusInPixels(s.ao, diag, depthScale, upp));
    }
    const size_t all = depth.data.size();
    j["sky"] = {{"pixels", sky}, {"share", all ? double(sky) / double(all) : 0.0},
                {"note", s.skip.sky ? "AO and the denoiser's last pass return at once on these pixels"
                                    : "skip.sky off: these pixels run the full estimate"}};
    j["adaptive"] = {{"enabled", s.ao.adaptive},
                     {"mean_sample_share", geo ? share / double(geo) : 1.0},
                     {"note", "mean share of the technique's full sample count taken per geometry pixel"}};
    return j;
}

} // namespace ssao
