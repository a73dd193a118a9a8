// HBAO's rows of the parameter table (group "hbao"; they apply while ao.technique = hbao).
// Defaults: HbaoSettings' initialisers (settings.h).
#include "settings/param_rows.h"
#include "techniques/hbao/hbao_pass.h"
#include "techniques/hbao/pack.h"
#include "techniques/hbao/technique.h"

namespace ssao {

namespace {
std::vector<Param> hbaoParams() {
    return {
        INT_ROW("hbao.directions", "Directions", hbao.directions, 1, HBAO_MAX_DIRECTIONS, "",
                "Screen directions around the pixel (Bavoil's D); each finds one horizon."),
        INT_ROW("hbao.steps", "Steps", hbao.steps, 1, HBAO_MAX_STEPS, "per direction",
                "Depth samples marched along each direction (Bavoil's S)."),
        FLOAT_ROW("hbao.tangent_bias", "Tangent bias", hbao.tangentBias, 0.0, 0.9, "sin(angle)",
                  "Horizons less than this far above the tangent plane occlude nothing: removes the "
                  "self-occlusion of tessellated or noisy surfaces (HBAO's angle bias)."),
        FLOAT_ROW("hbao.max_radius_px", "Max radius", hbao.maxRadiusPx, 2.0, 1024.0, "pixels",
                  "The radius projected to the screen is clamped to this: close-ups stay affordable."),
        ENUM_ROW("hbao.noise", "Noise", hbao.noise, AoNoise, kAoNoiseHelp, (aoNoiseChoices())),
        BOOL_ROW("hbao.pyramid", "Position MIPs", hbao.pyramid, kPyramidHelp),
    };
}
} // namespace

TechniqueInfo hbaoTechnique() {
    return {"hbao", "HBAO (Bavoil 2008)",
            "Horizon-based: the highest horizon above the tangent plane along D directions, linear falloff: "
            "Bavoil, Sainz, Dimitrov 2008 (seed 002), NVIDIA HBAO+",
            hbaoParams, onePass<HbaoPass>()};
}

} // namespace ssao
