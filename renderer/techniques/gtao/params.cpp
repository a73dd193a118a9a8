// GTAO's rows of the parameter table (group "gtao"; they apply while ao.technique = gtao).
// Defaults: GtaoSettings' initialisers (settings.h).
#include "settings/param_rows.h"
#include "techniques/gtao/gtao_pass.h"
#include "techniques/gtao/pack.h"
#include "techniques/gtao/technique.h"

namespace ssao {

namespace {
std::vector<Param> gtaoParams() {
    return {
        ENUM_ROW("gtao.quality", "Quality", gtao.quality, GtaoQuality,
                 "XeGTAO's presets, slices x steps per side: low 1x2, medium 2x2, high 3x3, ultra 9x3; "
                 "custom uses the two rows below.",
                 ({{"low", GtaoQuality::Low},
                   {"medium", GtaoQuality::Medium},
                   {"high", GtaoQuality::High},
                   {"ultra", GtaoQuality::Ultra},
                   {"custom", GtaoQuality::Custom}})),
        INT_ROW("gtao.slices", "Slices", gtao.slices, 1, GTAO_MAX_SLICES, "slices",
                "Directions around the view vector per pixel; each adds two horizon searches.")
            .onlyWhen("gtao.quality", {"custom"}),
        INT_ROW("gtao.steps", "Steps", gtao.steps, 1, GTAO_MAX_STEPS, "per side",
                "Depth samples along each side of a slice while searching the horizon.")
            .onlyWhen("gtao.quality", {"custom"}),
        FLOAT_ROW("gtao.radius_multiplier", "Radius multiplier", gtao.radiusMultiplier, 0.1, 5.0, "x radius",
                  "Search radius = AO radius x this; XeGTAO's 1.457 was fitted to its ray-traced reference "
                  "(a falloff needs a longer reach to match binary visibility within R)."),
        FLOAT_ROW("gtao.falloff_range", "Falloff range", gtao.falloffRange, 0.01, 1.0, "x radius",
                  "Occluders fade linearly to nothing over this last fraction of the search radius "
                  "(XeGTAO 0.615): no hard edge where a surface leaves the radius."),
        FLOAT_ROW("gtao.distribution_power", "Step distribution", gtao.distributionPower, 0.5, 4.0, "power",
                  "Step k of n lies at (k/n)^p of the radius: >1 samples more densely near the pixel, where "
                  "small creases are (XeGTAO 2)."),
        FLOAT_ROW("gtao.thin_compensation", "Thin occluders", gtao.thinCompensation, 0.0, 0.7, "",
                  "XeGTAO's heuristic: depth differences count (1 + t) times in the falloff, so thin objects "
                  "in front occlude less of what is behind them (0 = off)."),
        ENUM_ROW("gtao.noise", "Noise", gtao.noise, AoNoise, kAoNoiseHelp, (aoNoiseChoices())),
        BOOL_ROW("gtao.pyramid", "Position MIPs", gtao.pyramid, kPyramidHelp),
    };
}
} // namespace

TechniqueInfo gtaoTechnique() {
    return {"gtao", "GTAO (Jimenez 2016 / XeGTAO)",
            "Horizon-based, cosine-weighted visibility integrated analytically per slice: Jimenez et al. "
            "2016, Intel XeGTAO",
            gtaoParams, onePass<GtaoPass>()};
}

} // namespace ssao
