// The list of AO techniques. Adding one: its folder, one member in technique_settings.h and
// one entry here.
#include "techniques/gtao/technique.h"
#include "techniques/hbao/technique.h"
#include "techniques/kernel/technique.h"
#include "techniques/sao/technique.h"
#include "techniques/technique.h"
#include "techniques/technique_settings.h"
#include "techniques/vbao/technique.h"
#include "util/error.h"

#include "../../shaders/include/adaptive.h"

#include <algorithm>

namespace ssao {

const char* const kDefaultTechnique = "kernel"; // what a new Settings{} runs (base/shared_settings.h)

const std::vector<TechniqueInfo>& techniques() {
    static const std::vector<TechniqueInfo> list = {kernelTechnique(), saoTechnique(), hbaoTechnique(), gtaoTechnique(),
                                                   vbaoTechnique()};
    return list;
}

const TechniqueInfo& findTechnique(const std::string& id) {
    std::string known;
    for (const auto& t : techniques()) {
        if (t.id == id) return t;
        known += (known.empty() ? "" : "|") + t.id;
    }
    throw Error("unknown AO technique '" + id + "' (known: " + known + ")");
}

// What the settings need of the techniques (base/param.h), from the modules.
const std::vector<TechniqueRows>& registeredTechniques() {
    static const std::vector<TechniqueRows> rows = [] {
        std::vector<TechniqueRows> out;
        for (const auto& t : techniques())
            out.push_back({t.id, t.params(), bool(t.adaptive), t.deinterleave});
        return out;
    }();
    return rows;
}

std::string unphysicalReason(const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    return t.unphysical ? t.unphysical(s) : std::string();
}

bool usesPyramid(const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    return t.pyramid && t.pyramid(s);
}

bool deinterleaves(const Settings& s) {
    return s.ao.deinterleave && findTechnique(s.ao.technique).deinterleave && s.ao.resolution == AoResolution::Full &&
           !usesPyramid(s) && s.gbuffer.guardBandPx == 0 && !s.gbuffer.backFaces && s.ao.normals == NormalSource::GBuffer;
}

DenoiseSettings effectiveDenoise(const Settings& s) {
    if (s.denoise.kind != DenoiseKind::Auto) return s.denoise;
    DenoiseSettings d = findTechnique(s.ao.technique).denoiser;
    d.upsample = s.denoise.upsample; // how reduced AO returns to full size stays the user's choice
    return d;
}

double adaptiveShare(const Settings& s, float radiusPx) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    if (!s.ao.adaptive || !t.adaptive) return 1.0;
    const AdaptiveCount c = t.adaptive(s);
    if (c.full <= 0) return 1.0;
    const float r = std::max(radiusPx, 0.0f);
    const int n = c.march ? gpu::adaptiveSteps(s.ao.adaptivePx, c.full, r)
                          : gpu::adaptiveSamples(s.ao.adaptivePx, c.full, r);
    return double(n) / double(c.full);
}

} // namespace ssao
