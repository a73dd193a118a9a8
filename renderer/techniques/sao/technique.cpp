// SAO's rows of the parameter table (group "sao"; they apply while ao.technique = sao).
// Defaults: SaoSettings' initialisers (settings.h).
#include "techniques/sao/pack.h"
#include "techniques/sao/technique.h"
#include "techniques/one_block.h"
#include "techniques/shared_rows.h"

namespace ssao {

namespace {
std::vector<Param> saoParams() {
    return {
        INT_ROW("sao.samples", "Samples", sao.samples, 1, SAO_MAX_SAMPLES, "taps",
                "Taps on the spiral (SAO uses 11); more = less noise, linear cost."),
        FLOAT_ROW("sao.turns", "Spiral turns", sao.turns, 0.0, 32.0, "turns",
                  "How many times the spiral winds over the taps; pick it coprime with the tap count so "
                  "taps do not line up (SAO: 7 turns for 11 taps)."),
        FLOAT_ROW("sao.intensity", "Intensity", sao.intensity, 0.0, 10.0, "",
                  "Alchemy AO's sigma: scales the summed obscurance before it is subtracted from 1."),
        FLOAT_ROW("sao.bias", "Bias", sao.bias, 0.0, 0.5, "x radius",
                  "Alchemy AO's beta: an occluder must rise this far (a fraction of the radius) above the "
                  "tangent plane; removes self-occlusion of tessellated surfaces."),
        NOISE_ROW("sao.noise", sao.noise),
        PYRAMID_ROW("sao.pyramid", sao.pyramid),
    };
}

// What the generic one-block pass needs of SAO (techniques/ao_pass.h).
struct SaoModule : BlockModule<SaoSettings, gpu::SaoConstants, &TechniqueSettings::sao, packSaoConstants> {
    static constexpr const char* shader = "techniques/sao/sao.frag";
    static constexpr float pyramidOffset = kSaoMipOffset;
};
} // namespace

TechniqueInfo saoTechnique() {
    TechniqueInfo t = oneBlockTechnique<SaoModule>("sao", "SAO / Alchemy AO (McGuire 2011/2012)",
            "Spiral taps, falloff-weighted obscurance max(0, v.n - bias)/(v.v + eps): McGuire et al. 2011 "
            "(Alchemy AO), McGuire, Mara, Luebke 2012 (SAO)",
                    saoParams);
    t.adaptive = [](const Settings& s) { return AdaptiveCount{s.sao.samples, false}; }; // taps on a disc
    // denoise.kind = auto: one depth- and normal-aware bilateral pass, 5x5, lowers the raw AO's
    // error on all 5 scenes of the denoiser sweep (mean -0.0173; box4 raised it by up to 0.022).
    t.denoiser.kind = DenoiseKind::Bilateral;
    t.denoiser.passes = 1;
    t.denoiser.halfWidth = 2;
    // Its stated bounds (technique.h): its estimator weighs far occluders less than the closed form.
    t.cornerBound = 0.12, t.levelsCornerBound = 0.12;
    t.levels = {{"low", {"sao.samples=8", "sao.turns=3"}},
                {"medium", {"sao.samples=11", "sao.turns=7"}},
                {"high", {"sao.samples=24", "sao.turns=7"}},
                {"ultra", {"sao.samples=48", "sao.turns=11"}}};
    t.tuned = {"sao.intensity", "sao.bias"};
    return t;
}

} // namespace ssao
