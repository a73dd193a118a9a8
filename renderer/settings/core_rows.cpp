// The core rows of the parameter table (settings/params.h): the G-buffer, the AO every technique
// shares, the denoiser, the temporal filter, the composite and the skips, with ao.technique's
// choices and the rows' conditions taken from the registered techniques.
#include "settings/core_rows.h"

#include "base/param_rows.h"
#include "techniques/registry.h"
#include "settings/settings.h"

namespace ssao {

namespace {

using T = Param::Type;

// ao.technique: one choice per registered module, mapped by id.
Param techniqueRow() {
    Param t;
    t.key = "ao.technique", t.label = "Technique", t.type = T::Enum;
    t.help = "The AO estimator; each technique adds its own parameters below.";
    for (const auto& info : registeredTechniques())
        t.choices.push_back(info.id);
    t.min = 0, t.max = double(t.choices.size() - 1);
    t.get = [](const Settings& s) {
        const auto& list = registeredTechniques();
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i].id == s.ao.technique) return double(i);
        return 0.0; // not a registered technique: Renderer::setSettings refuses it by name
    };
    t.set = [](Settings& s, double v) { s.ao.technique = registeredTechniques().at(size_t(v)).id; };
    return t;
}

// The ids of the registered techniques that have a capability (TechniqueRows' flags): the techniques
// a shared row applies to.
std::vector<std::string> techniquesWith(bool TechniqueRows::*capability) {
    std::vector<std::string> ids;
    for (const auto& info : registeredTechniques())
        if (info.*capability) ids.push_back(info.id);
    return ids;
}

std::vector<Param> coreRows() {
    std::vector<Param> rows = {
        // ---- G-buffer -------------------------------------------------------------------------
        ENUM_ROW(
            "gbuffer.position_format", "Position format", gbuffer.positionFormat, TargetFormat,
            "Precision of the view-space position target; rgba16f shows fp16 staircase acne at distance.",
            ({{"rgba16f", TargetFormat::RGBA16F}, {"rgba32f", TargetFormat::RGBA32F}})),
        ENUM_ROW("gbuffer.normal_format", "Normal format", gbuffer.normalFormat, TargetFormat,
                 "Normal target: float, or 8-bit (n+1)/2 as in seed 003 (renormalised after decoding).",
                 ({{"rgba16f", TargetFormat::RGBA16F},
                   {"rgba32f", TargetFormat::RGBA32F},
                   {"rgba8", TargetFormat::RGBA8}})),
        INT_ROW("gbuffer.guard_band_px", "Guard band", gbuffer.guardBandPx, 0, 256, "pixels",
                "Positions also rendered this many pixels beyond each edge of the frame (same pixel grid), so "
                "taps near the border see what is just off screen (G3D's demos use 64). SAO, HBAO, GTAO and the "
                "bitmask read it; 0 = none."),
        BOOL_ROW("gbuffer.back_faces", "Back faces", gbuffer.backFaces,
                 "A second geometry pass keeps the nearest surface facing away from the camera (by its normal): "
                 "where it lies behind a tap, the bitmask hides the sectors down to it - the surface's true "
                 "thickness - instead of the assumed vbao.thickness."),
        BOOL_ROW("gbuffer.second_layer", "Second layer", gbuffer.secondLayer,
                 "A second geometry pass keeps, per pixel, the nearest surface facing the camera behind the one "
                 "seen (depth peeling, as Mara et al.'s deep G-buffer): the bitmask then also hides the sectors of "
                 "what the depth buffer hides - a wall behind a thin object, a part behind a part.")
            .onlyWhen("ao.technique", techniquesWith(&TechniqueRows::secondLayer)),
        FLOAT_ROW("gbuffer.second_layer_separation", "Layer separation", gbuffer.secondLayerSeparation, 0.0, 0.1,
                  "x diagonal",
                  "How far behind the first surface the second must lie (a fraction of the scene's diagonal), so a "
                  "surface is not found again as its own second layer (Mara et al.'s minimum separation).")
            .onlyWhen("gbuffer.second_layer", {"true"}),
        ENUM_ROW("gbuffer.second_layer_build", "Layer built by", gbuffer.secondLayerBuild, SecondLayerBuild,
                 "peel: a second geometry pass against this frame's first layer (exact). previous: the G-buffer's "
                 "own pass keeps it, against the previous frame's first layer reprojected (Mara et al.'s single "
                 "pass: no second pass, every hidden fragment shaded; what the last frame did not see is missing).",
                 ({{"peel", SecondLayerBuild::Peel}, {"previous", SecondLayerBuild::Previous}}))
            .onlyWhen("gbuffer.second_layer", {"true"}),
        // ---- AO (every technique) -------------------------------------------------------------
        techniqueRow(),
        ENUM_ROW(
            "ao.radius_mode", "Radius in", ao.radiusMode, RadiusMode,
            "Unit of the AO radius: world (scene units), scene (fraction of the scene's bounding-box "
            "diagonal, follows the scene) or screen (pixels at each pixel's depth).",
            ({{"world", RadiusMode::World}, {"scene", RadiusMode::Scene}, {"screen", RadiusMode::Screen}})),
        FLOAT_ROW("ao.radius", "World radius", ao.radius, 1e-4, 1e4, "scene units",
                  "World-size of the sampling kernel: how far away geometry can still occlude.")
            .onlyWhen("ao.radius_mode", {"world"}),
        FLOAT_ROW("ao.radius_scene", "Scene radius", ao.radiusScene, 1e-4, 0.5, "x diagonal",
                  "Radius as a fraction of the scene's bounding-box diagonal (0.05 = 5 %), so it follows the "
                  "scene's scale (metres or millimetres alike).")
            .onlyWhen("ao.radius_mode", {"scene"}),
        FLOAT_ROW(
            "ao.radius_px", "Screen radius", ao.radiusPx, 1.0, 512.0, "pixels",
            "Radius in pixels at each pixel's depth: the kernel covers the same screen area near and far.")
            .onlyWhen("ao.radius_mode", {"screen"}),
        FLOAT_ROW("ao.power", "Power", ao.power, 0.1, 16.0, "",
                  "Contrast: AO = visibility^power; >1 darkens occluded areas, <1 lightens (seed 001)."),
        ENUM_ROW(
            "ao.resolution", "Resolution", ao.resolution, AoResolution,
            "Resolution of the AO pass relative to the G-buffer; the denoise stage brings it back to full "
            "size (fewer pixels = faster, blurrier).",
            ({{"full", AoResolution::Full},
              {"half", AoResolution::Half},
              {"quarter", AoResolution::Quarter}})),
        ENUM_ROW("ao.normals", "Normals", ao.normals, NormalSource,
                 "Where the AO pass takes the surface normal: the G-buffer, or reconstructed from the positions "
                 "alone (as an engine without a normal target must), using on each axis the neighbour with the "
                 "smaller depth difference so silhouettes do not bend the normal.",
                 ({{"gbuffer", NormalSource::GBuffer}, {"depth", NormalSource::Depth}})),
        BOOL_ROW("ao.adaptive", "Adaptive samples", ao.adaptive,
                 "ASSAO/CACAO-style: pixels whose radius spans few pixels (far away, or a small radius) "
                 "take fewer samples - a march one step per 'pixels per sample' of radius, an area sampler "
                 "one tap per its square of the disc. Time saved and error change: docs/bench/skips.md. "
                 "(The kernel's samples are a fixed set: it keeps them all.)")
            .onlyWhen("ao.technique", techniquesWith(&TechniqueRows::adaptive)),
        FLOAT_ROW("ao.adaptive_px", "Pixels per sample", ao.adaptivePx, 1.0, 32.0, "pixels",
                  "Adaptive samples: radius in pixels each march step (or each tap's square of the disc) "
                  "covers before the count is cut; 1 keeps every step that lands on a new pixel.")
            .onlyWhen("ao.adaptive", {"true"}),
        BOOL_ROW("ao.deinterleave", "Deinterleave", ao.deinterleave,
                 "Cache-aware sampling (NVIDIA gl_ssao, HBAO+): the G-buffer split into 16 quarter-size layers, "
                 "the AO computed over each with one jitter for the whole layer, then interleaved back. Taps land "
                 "on a 4-pixel grid. Pays where neighbouring pixels sharing a texture cache line matters (gl_ssao: "
                 "1.9x for HBAO on a Quadro M6000); measured on llvmpipe in docs/bench/skips.md. Full resolution "
                 "only; not with the position pyramid, guard band, back-face layer or normals from depth.")
            .onlyWhen("ao.technique", techniquesWith(&TechniqueRows::deinterleave)),
        // ---- Denoise --------------------------------------------------------------------------
        ENUM_ROW("denoise.kind", "Denoise", denoise.kind, DenoiseKind,
                 "Removes the sampling noise: auto (default: the technique's own choice, measured on the benchmark to "
                 "lower its raw error on every bench scene - bilateral for the kernel and SAO, none for HBAO, GTAO and "
                 "the bitmask, whose noise is finer than the detail a filter erases), none, 4x4 box (seed 004: taps -2..+1, shifted half a pixel), "
                 "box4c (the same width centred: taps -1.5..+1.5 read bilinearly), gaussian (seed 003) - separable, "
                 "upsampling reduced-resolution AO bilinearly - or bilateral: edge-aware, weighted by depth "
                 "and normal similarity so AO does not bleed across silhouettes, with a joint-bilateral upsample.",
                 ({{"auto", DenoiseKind::Auto},
                   {"none", DenoiseKind::None},
                   {"box4", DenoiseKind::Box4},
                   {"box4c", DenoiseKind::Box4Centred},
                   {"gaussian", DenoiseKind::Gaussian},
                   {"bilateral", DenoiseKind::Bilateral}})),
        FLOAT_ROW("denoise.sigma", "Sigma", denoise.sigma, 0.1, 32.0, "taps",
                  "Gaussian standard deviation (also the bilateral's spatial term); weight = exp(-d^2 / (2 sigma^2)).")
            .onlyWhen("denoise.kind", {"gaussian", "bilateral"}),
        INT_ROW("denoise.half_width", "Half-width", denoise.halfWidth, 0, 32, "taps",
                "Taps each side of the centre (2 gives the seed's 5x5; the bilateral uses at most 8).")
            .onlyWhen("denoise.kind", {"gaussian", "bilateral"}),
        FLOAT_ROW(
            "denoise.spacing", "Tap spacing", denoise.spacing, 0.25, 16.0, "pixels",
            "Distance between gaussian taps (seed 003 blurRadius); >1 widens the blur without more taps.")
            .onlyWhen("denoise.kind", {"gaussian"}),
        FLOAT_ROW("denoise.sharpness", "Edge sharpness", denoise.sharpness, 0.0, 200.0, "",
                  "Bilateral: a neighbour whose depth differs by a fraction f of the pixel's weighs "
                  "exp(-(f x sharpness)^2); higher keeps AO from crossing depth edges, 0 ignores depth.")
            .onlyWhen("denoise.kind", {"bilateral"}),
        INT_ROW("denoise.passes", "Passes", denoise.passes, 1, 3, "",
                "Bilateral: how many times the edge-aware filter runs (XeGTAO's denoiser runs 1-3).")
            .onlyWhen("denoise.kind", {"bilateral"}),
        FLOAT_ROW("denoise.ao_sigma", "AO range", denoise.aoSigma, 0.0, 1.0, "AO",
                  "Bilateral: a neighbour whose AO differs from the pixel's by d weighs exp(-(d / range)^2), so "
                  "detail that stands out of the noise (ribs, seams) is kept; 0 = off (depth and normal only).")
            .onlyWhen("denoise.kind", {"bilateral"}),
        ENUM_ROW("denoise.upsample", "Upsample", denoise.upsample, DenoiseUpsample,
                 "Reduced-resolution AO back to full size: joint (default) filters at the AO's resolution, then one "
                 "joint-bilateral 2x2 upsample weighted by depth, so AO does not bleed across silhouettes; filter lets "
                 "the filter's last pass run at full resolution and upsample (bilinearly; the bilateral with its own "
                 "weights) - the behaviour before joint.",
                 ({{"joint", DenoiseUpsample::Joint}, {"filter", DenoiseUpsample::Filter}}))
            .onlyWhen("ao.resolution", {"half", "quarter"}),
        // ---- Temporal ---------------------------------------------------------------------------
        BOOL_ROW("temporal.enabled", "Temporal", temporal.enabled,
                 "Accumulate the denoised AO over frames, each with new noise, reprojecting the history "
                 "through the previous camera (headless: renders that many frames)."),
        INT_ROW("temporal.frames", "Frames", temporal.frames, 1, 64, "frames",
                "Frames blended after a change (running mean: frame k weighs 1/k); then the image is final "
                "and nothing re-runs.")
            .onlyWhen("temporal.enabled", {"true"}),
        INT_ROW("temporal.moving_frames", "Frames in motion", temporal.movingFrames, 1, 64, "frames",
                "While the camera moves, the history counts as at most this many frames: a shorter memory "
                "lags less behind the view and blurs less with each reprojection, at the price of more noise.")
            .onlyWhen("temporal.enabled", {"true"}),
        FLOAT_ROW("temporal.plane_tolerance", "Plane tolerance", temporal.planeTolerance, 0.05, 16.0, "pixels",
                  "A history texel is kept only where the surface it recorded lies this close to the pixel's "
                  "tangent plane, in widths of one pixel at that depth (disocclusion: no ghost trails, and no "
                  "other surface's AO mixed in, near or far).")
            .onlyWhen("temporal.enabled", {"true"}),
        // ---- Composite ------------------------------------------------------------------------
        FLOAT_ROW("composite.ambient", "Ambient", composite.ambient, 0.0, 4.0, "",
                  "Ambient term strength: ambient * albedo * AO (seed 004 uses 0.1 with a bright light)."),
        FLOAT_ROW("composite.light", "Light", composite.light, 0.0, 10.0, "",
                  "Intensity of the one point light at the camera (0 shows ambient * AO only)."),
        BOOL_ROW("composite.ao", "Apply AO", composite.useAo,
                 "Multiply the ambient term by AO; off shows the same frame without AO."),
        // ---- Skips: work the frame does not need ----------------------------------------------
        BOOL_ROW("skip.sky", "Skip sky", skip.sky,
                 "AO and the denoiser's last pass return at once where there is no geometry (off: sky "
                 "pixels run the full estimate, then are discarded - same image, to measure the saving)."),
        BOOL_ROW("skip.cull", "Frustum culling", skip.cull,
                 "The G-buffer pass does not draw meshes whose bounding box lies outside the view."),
        BOOL_ROW("skip.hidden_faces", "Cull hidden faces", skip.hiddenFaces,
                 "The G-buffer culls the back faces of closed solids (each edge shared by two triangles wound "
                 "opposite ways, found at load), which a front face of the same solid always hides while the "
                 "camera is outside it; open meshes, cut-outs and solids the near plane reaches are drawn whole. "
                 "The same image."),
        BOOL_ROW("skip.occluded", "Occlusion culling", skip.occluded,
                 "The G-buffer draws first the meshes that were visible last frame, then tests the bounding box "
                 "of each other mesh against that depth (occlusion queries) and draws only those it shows: parts "
                 "inside others are not drawn (2CylinderEngine: 87 of 115 at its camera). The same surfaces (where two "
                 "surfaces z-fight, up to the depth buffer's rounding); the first frame of a scene draws everything."),
        BOOL_ROW("skip.unused_targets", "Skip unused targets", skip.unusedTargets,
                 "The G-buffer writes only the targets that the technique, the denoiser, the composite or a "
                 "shown buffer reads (e.g. no albedo while only AO is shown)."),
        BOOL_ROW("skip.fused_upsample", "Fused upsample", skip.fusedUpsample,
                 "Reduced AO with the joint upsample: the composite upsamples it itself and the full-resolution AO "
                 "is not written, wherever nothing else reads it (a composite view with the reference off and the "
                 "cursor off the image); the same image. Off by default: on llvmpipe it saves nothing "
                 "(`ssaolab skips`), and each time the cursor enters or leaves the image the graph changes.")
            .onlyWhen("ao.resolution", {"half", "quarter"}),
        BOOL_ROW("skip.motion_lod", "Simplify while moving", skip.motionLod,
                 "While the camera moves, the G-buffer of a scene of 40k triangles or more draws a copy with its "
                 "vertices clustered into cells (1/96 to 1/768 of the diagonal: the coarsest whose cell covers at "
                 "most a pixel of the moving frame; none where no level is that fine): llvmpipe sets up "
                 "every triangle on one thread whatever the resolution, so a CAD model's moving frame is "
                 "bound by its triangles. The still frame draws the full mesh; headless renders never move."),
    };
    return rows;
}

} // namespace

std::vector<Param> coreParamRows() {
    return coreRows();
}

} // namespace ssao
