// Visibility-bitmask rows of the parameter table (group "vbao"; they apply while
// ao.technique = vbao). Defaults: VbaoSettings' initialisers (settings.h).
#include "techniques/vbao/pack.h"
#include "techniques/vbao/technique.h"
#include "techniques/one_block.h"
#include "techniques/shared_rows.h"

namespace ssao {

namespace {
std::vector<Param> vbaoParams() {
    return {
        INT_ROW("vbao.slices", "Slices", vbao.slices, 1, VBAO_MAX_SLICES, "slices",
                "Directions around the view vector per pixel, each a 32-sector visibility mask."),
        INT_ROW("vbao.steps", "Steps", vbao.steps, 1, VBAO_MAX_STEPS, "per side",
                "Depth samples along each side of a slice; each marks the sectors it hides."),
        FLOAT_ROW("vbao.thickness", "Thickness", vbao.thickness, 0.0, 4.0, "x radius",
                  "Assumed depth of every surface seen: a sample hides the sectors between its front and "
                  "its front pushed this far back. Small: thin objects let light pass behind them; large: "
                  "behaves like a horizon (GTAO)."),
        FLOAT_ROW("vbao.distribution_power", "Step distribution", vbao.distributionPower, 0.5, 4.0, "power",
                  "Step k of n lies at (k/n)^p of the radius: >1 samples more densely near the pixel."),
        BOOL_ROW("vbao.true_thickness", "True thickness", vbao.trueThickness,
                 "Where the back-face layer holds a surface's far side, its sectors end there even when that is "
                 "thinner than the assumed thickness. Off: the far side only ever lengthens a sample (rays "
                 "between sparse samples of a thin wall would pass). docs/bench/layers.md measures both.")
            .onlyWhen("gbuffer.back_faces", {"true"}),
        NOISE_ROW("vbao.noise", vbao.noise),
        PYRAMID_ROW("vbao.pyramid", vbao.pyramid),
    };
}

// What the generic one-block pass needs of the visibility bitmask (techniques/ao_pass.h).
struct VbaoModule : BlockModule<VbaoSettings, gpu::VbaoConstants, &TechniqueSettings::vbao, packVbaoConstants> {
    static constexpr const char* shader = "techniques/vbao/vbao.frag";
    static constexpr float pyramidOffset = kXeGtaoMipOffset;
};
} // namespace

TechniqueInfo vbaoTechnique() {
    TechniqueInfo t = oneBlockTechnique<VbaoModule>("vbao", "Visibility bitmask (Therrien 2023)",
            "GTAO's slices with a 32-sector occlusion bitmask per slice and an assumed thickness: Therrien, "
            "Levesque, Gilet 2023",
                    vbaoParams);
    t.deinterleave = true;
    t.secondLayer = true; // each layer's interval marks its sectors (vbao.frag)
    t.adaptive = [](const Settings& s) { return AdaptiveCount{s.vbao.steps, true}; };
    // denoise.kind = auto: none. Every filter of the denoiser sweep raised its raw error on some
    // scene (box4 by up to 0.085; an AO-range bilateral by 0.0008): its noise is finer than the detail a
    // filter erases.

    // Its stated bounds (technique.h): binary visibility within R, the reference's definition.
    t.cornerBound = 0.05, t.levelsCornerBound = 0.06;
    t.levels = {{"low", {"vbao.slices=2", "vbao.steps=4"}},
                {"medium", {"vbao.slices=2", "vbao.steps=8"}},
                {"high", {"vbao.slices=4", "vbao.steps=8"}},
                {"ultra", {"vbao.slices=4", "vbao.steps=16"}}};
    t.tuned = {"vbao.thickness", "vbao.distribution_power"};
    // vbao-half-LEVEL: vbao-LEVEL at half resolution (its own file sets that); vbao-max: the ultra
    // level's fitted rows at 8 slices x 24 steps.
    for (const char* level : {"low", "medium", "high", "ultra"})
        t.derived.push_back({std::string("vbao-half-") + level, std::string("vbao-") + level, {}});
    t.derived.push_back({"vbao-max", "vbao-ultra", {"vbao.slices=8", "vbao.steps=24"}});
    return t;
}

} // namespace ssao
