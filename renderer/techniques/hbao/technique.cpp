// HBAO's rows of the parameter table (group "hbao"; they apply while ao.technique = hbao).
// Defaults: HbaoSettings' initialisers (settings.h).
#include "techniques/hbao/pack.h"
#include "techniques/hbao/technique.h"
#include "techniques/one_block.h"
#include "techniques/shared_rows.h"

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
        NOISE_ROW("hbao.noise", hbao.noise),
        PYRAMID_ROW("hbao.pyramid", hbao.pyramid),
    };
}

// What the generic one-block pass needs of HBAO (techniques/ao_pass.h).
struct HbaoModule : BlockModule<HbaoSettings, gpu::HbaoConstants, &TechniqueSettings::hbao, packHbaoConstants> {
    static constexpr const char* shader = "techniques/hbao/hbao.frag";
    static constexpr float pyramidOffset = kSaoMipOffset;
};
} // namespace

TechniqueInfo hbaoTechnique() {
    TechniqueInfo t = oneBlockTechnique<HbaoModule>("hbao", "HBAO (Bavoil 2008)",
            "Horizon-based: the highest horizon above the tangent plane along D directions, linear falloff: "
            "Bavoil, Sainz, Dimitrov 2008 (seed 002), NVIDIA HBAO+",
                    hbaoParams);
    t.deinterleave = true;
    t.adaptive = [](const Settings& s) { return AdaptiveCount{s.hbao.steps, true}; };
    // denoise.kind = auto: none. Every filter of the denoiser sweep raised its raw error on some
    // scene (box4 by up to 0.024; an AO-range bilateral by 0.002): its noise is finer than the detail a
    // filter erases.

    // Its stated bounds (technique.h): its linear falloff weighs far occluders less than the closed form.
    t.cornerBound = 0.15, t.levelsCornerBound = 0.15;
    t.levels = {{"low", {"hbao.directions=4", "hbao.steps=3"}},
                {"medium", {"hbao.directions=6", "hbao.steps=4"}},
                {"high", {"hbao.directions=8", "hbao.steps=4"}},
                {"ultra", {"hbao.directions=8", "hbao.steps=8"}}};
    t.tuned = {"hbao.tangent_bias"};
    return t;
}

} // namespace ssao
