// GTAO as a module: its rows of the parameter table (group "gtao"; they apply while
// ao.technique = gtao), what the one-block pass needs and its capabilities.
// Defaults: GtaoSettings' initialisers (settings.h).
#include "techniques/gtao/pack.h"
#include "techniques/gtao/technique.h"
#include "techniques/one_block.h"
#include "techniques/shared_rows.h"

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
        NOISE_ROW("gtao.noise", gtao.noise),
        PYRAMID_ROW("gtao.pyramid", gtao.pyramid),
    };
}

// What the generic one-block pass needs of GTAO (techniques/ao_pass.h).
struct GtaoModule : BlockModule<GtaoSettings, gpu::GtaoConstants, &TechniqueSettings::gtao, packGtaoConstants> {
    static constexpr const char* shader = "techniques/gtao/gtao.frag";
    static constexpr float pyramidOffset = kXeGtaoMipOffset;
};
} // namespace

TechniqueInfo gtaoTechnique() {
    TechniqueInfo t = oneBlockTechnique<GtaoModule>("gtao", "GTAO (Jimenez 2016 / XeGTAO)",
            "Horizon-based, cosine-weighted visibility integrated analytically per slice: Jimenez et al. "
            "2016, Intel XeGTAO",
                    gtaoParams);
    t.deinterleave = true;
    t.secondLayer = true; // the surface behind a tap is a candidate horizon (gtao.frag)
    t.adaptive = [](const Settings& s) { // its quality presets set the steps
        int slices = 0, steps = 0;
        gtaoSlicesSteps(s.gtao, slices, steps);
        return AdaptiveCount{steps, true};
    };
    // denoise.kind = auto: none. Every filter of the denoiser sweep raised its raw error on some
    // scene (box4 by up to 0.063; an AO-range bilateral by 0.0006).

    // Its stated bounds (technique.h): it integrates the quantity the closed form describes.
    t.cornerBound = 0.10, t.levelsCornerBound = 0.12;
    t.levels = {{"low", {"gtao.quality=low"}},
                {"medium", {"gtao.quality=medium"}},
                {"high", {"gtao.quality=high"}},
                {"ultra", {"gtao.quality=ultra"}}};
    t.tuned = {"gtao.radius_multiplier", "gtao.falloff_range", "gtao.distribution_power"};
    return t;
}

} // namespace ssao
