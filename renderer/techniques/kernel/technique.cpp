// Kernel SSAO as a module: its rows of the parameter table (group "kernel"; they apply while
// ao.technique = kernel). Defaults: KernelSettings' initialisers (settings.h).
#include "base/param_rows.h"
#include "techniques/kernel/kernel_pass.h"
#include "techniques/kernel/technique.h"

namespace ssao {

namespace {
std::vector<Param> kernelParams() {
    return {
        ENUM_ROW("kernel.shape", "Kernel", kernel.shape, KernelShape,
                 "hemisphere: samples above the surface; sphere (Crytek): half the samples start inside, "
                 "so flat surfaces read ~50% occluded.",
                 ({{"hemisphere", KernelShape::Hemisphere}, {"sphere", KernelShape::Sphere}})),
        BOOL_ROW("kernel.separable", "Separable", kernel.separable,
                 "Seed 003: two sample sets in the x-z and y-z tangent planes (N each, normalised by 2N)."),
        INT_ROW("kernel.samples", "Samples", kernel.samples, 1, 256, "samples",
                "Kernel samples per pixel (per plane when separable); more = less noise, linear cost."),
        FLOAT_ROW(
            "kernel.bias", "Bias", kernel.bias, 0.0, 1.0, "x radius",
            "Depth margin before a sample counts as occluded, as a fraction of the radius (LearnOpenGL's "
            "0.025 at radius 0.5 is 0.05), so it scales with the scene; removes self-occlusion acne, too "
            "much loses contact shadows."),
        ENUM_ROW(
            "kernel.range_check", "Range check", kernel.rangeCheck, RangeCheck,
            "Fades occluders far in depth from the pixel: smoothstep(radius/|dz|) (seed 004), hard "
            "|dz|<radius (seed 003) or off (dark halos behind silhouettes).",
            ({{"smoothstep", RangeCheck::Smoothstep}, {"hard", RangeCheck::Hard}, {"off", RangeCheck::Off}})),
        ENUM_ROW("kernel.depth_test", "Depth test", kernel.depthTest, DepthTest,
                 "sample: occluded if the surface is in front of the sample (seeds 000/004); fragment: if it "
                 "is behind the pixel itself (seed 003).",
                 ({{"sample", DepthTest::Sample}, {"fragment", DepthTest::Fragment}})),
        ENUM_ROW(
            "kernel.noise", "Rotation noise", kernel.noise, Noise,
            "Per-pixel kernel rotation: a tiled 4x4 texture (noise the denoiser removes) or none (banding).",
            ({{"tex4x4", Noise::Tex4x4}, {"none", Noise::None}})),
        INT_ROW("kernel.seed", "Seed", kernel.seed, 0, 1000000, "",
                "Random seed of the kernel and noise; change it to see which artefacts are sampling luck."),
        ENUM_ROW(
            "kernel.position_source", "Position source", kernel.positionSource, PositionSource,
            "Read positions from the G-buffer target, or reconstruct them from the depth buffer (seed 001).",
            ({{"gbuffer", PositionSource::GBuffer}, {"depth", PositionSource::Depth}})),
        ENUM_ROW(
            "kernel.offscreen", "Off-screen samples", kernel.offscreen, Offscreen,
            "Samples projecting outside the screen: skip (count as open) or clamp to the edge texel (seeds).",
            ({{"skip", Offscreen::Skip}, {"clamp", Offscreen::Clamp}})),
        ENUM_ROW("kernel.own_texel", "Own-texel samples", kernel.ownTexel, OwnTexel,
                 "A sample that projects into its own pixel's texel compares the surface with itself, half a "
                 "pixel off: open counts it as unoccluded (no acne at small radii or bias); test tests it like "
                 "any other sample (the seeds: self-occlusion acne where the bias is too small).",
                 ({{"open", OwnTexel::Open}, {"test", OwnTexel::Test}})),
    };
}

// The seeds' artefacts, kept selectable on purpose (the seed presets reproduce them).
std::string kernelUnphysical(const Settings& s) {
    if (s.kernel.shape == KernelShape::Sphere)
        return "the Crytek sphere kernel: half its samples start below any surface (seed 000's false occlusion)";
    if (s.kernel.bias == 0.0f)
        return "no bias: samples just above a surface compare with the depth of a texel up to half a pixel away "
               "(seed 000's self-occlusion acne, which the bias exists to remove)";
    if (s.kernel.depthTest == DepthTest::Fragment)
        return "seed 003's test against the pixel's own depth: a surface sloping away reads as occluded";
    return "";
}
} // namespace

TechniqueInfo kernelTechnique() {
    TechniqueInfo t;
    t.id = "kernel", t.label = "Kernel SSAO (seeds)";
    t.summary = "N samples in a hemisphere (or sphere) kernel tested against depth: Crytek 2007, Chapman 2013, "
                "LearnOpenGL";
    t.params = kernelParams;
    t.makePasses = onePass<KernelPass>();
    t.unphysical = kernelUnphysical; // no adaptive count (a fixed kernel), no pyramid
    t.staticNoise = [](const Settings& s) { return s.kernel.noise == Noise::None; };
    // denoise.kind = auto: one depth- and normal-aware bilateral pass, 5x5, lowers the raw AO's
    // error on all 5 scenes of the denoiser sweep (mean -0.0044; box4 raised it by up to 0.053).
    t.denoiser.kind = DenoiseKind::Bilateral;
    t.denoiser.passes = 1;
    t.denoiser.halfWidth = 2;
    // Its stated bounds (technique.h): the seeds' kernel counts depth hits, not cosine-weighted
    // visibility, so it is held loosely.
    t.cornerBound = 0.25, t.levelsCornerBound = 0.25;
    t.levels = {{"low", {"kernel.samples=16"}}, {"medium", {"kernel.samples=32"}}, {"high", {"kernel.samples=64"}}};
    t.tuned = {"kernel.bias"};
    return t;
}

} // namespace ssao
