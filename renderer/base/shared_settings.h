// What a person sets (units, meaning) — not what the GPU sees: each pass packs its own constants
// with one pure function. These are the blocks every technique and pass shares; Settings, the
// whole, adds one member per technique (techniques/technique_settings.h). The member initialisers
// are the one place defaults live; the parameter table (settings/core_rows.cpp plus each technique's
// rows) reads them from Settings{}.
#pragma once
#include <string>

namespace ssao {

struct Settings; // techniques/technique_settings.h

// The technique a new Settings{} uses; defined beside the registry (techniques/registry.cpp), the
// one place outside a technique's folders that names it.
extern const char* const kDefaultTechnique;

enum class TargetFormat { RGBA16F, RGBA32F, RGBA8 }; // RGBA8: normals only, stored (n+1)/2
enum class RadiusMode { World, Scene, Screen };
enum class AoResolution { Full, Half, Quarter };
enum class NormalSource { GBuffer, Depth }; // SSAO_NORMALS_* (bindings.h)
// Auto: the technique's own denoiser (TechniqueInfo::denoiser), the one measured to lower its raw error.
enum class DenoiseKind { Auto, None, Box4, Box4Centred, Gaussian, Bilateral };
// How reduced-resolution AO returns to full size: Joint filters at the AO's resolution, then one
// joint-bilateral 2x2 upsample (passes/upsample_joint.frag); Filter lets the filter's last pass run
// at full resolution and upsample (bilinearly; the bilateral with its own depth and normal weights).
enum class DenoiseUpsample { Joint, Filter };
// How the second depth layer is built (passes/second_layer_pass.h): Peel, a second geometry pass
// against this frame's first layer (exact); Previous, inside the G-buffer's own pass against the
// previous frame's first layer reprojected (Mara et al. 2016's single pass).
enum class SecondLayerBuild { Peel, Previous };

struct GBufferSettings {
    TargetFormat positionFormat = TargetFormat::RGBA32F;
    TargetFormat normalFormat = TargetFormat::RGBA16F;
    int guardBandPx = 0; // positions also rendered this many pixels beyond each edge (0 = none)
    bool backFaces = false; // the nearest surface facing away, as a linear depth (true thickness)
    // A second depth layer (Mara et al. 2016's deep G-buffer, by depth peeling): per pixel the
    // nearest surface facing the camera at least secondLayerSeparation x the scene's diagonal
    // behind the first, so taps see what the first layer hides.
    bool secondLayer = false;
    float secondLayerSeparation = 0.005f;
    SecondLayerBuild secondLayerBuild = SecondLayerBuild::Peel;
};

// What every AO technique shares: which one runs, its radius (in one of three unit systems),
// the final contrast and the resolution the AO is computed at.
struct AoSettings {
    std::string technique = kDefaultTechnique; // id of a registered technique (techniques/registry.cpp)
    RadiusMode radiusMode = RadiusMode::Scene;
    float radius = 0.5f;       // world mode: scene units
    float radiusScene = 0.05f; // scene mode: fraction of the scene's bounding-box diagonal
    float radiusPx = 24.0f;    // screen mode: pixels, at the shaded pixel's depth (N8AO, three.js GTAO)
    float power = 1.0f;        // AO = visibility^power (seed 001; XeGTAO FinalValuePower)
    AoResolution resolution = AoResolution::Full;
    NormalSource normals = NormalSource::GBuffer; // depth: reconstructed from positions (no normal target)
    // ASSAO/CACAO-style: a pixel whose radius spans few pixels takes fewer samples: a march one
    // step per adaptivePx pixels of radius, an area sampler one tap per adaptivePx^2 pixels of the
    // disc, never below 2 steps / 4 taps nor above the technique's own count.
    bool adaptive = false;
    float adaptivePx = 4.0f;
    // Deinterleaved ("cache-aware") sampling (techniques/deinterleave.h): 16 quarter-size layers,
    // one jitter each; for the techniques that can (TechniqueInfo::deinterleave), at full resolution
    // without the pyramid, guard band, back-face layer or normals from depth.
    bool deinterleave = false;
};

struct DenoiseSettings {
    DenoiseKind kind = DenoiseKind::Auto;
    float sigma = 1.5f;   // gaussian standard deviation, in taps
    int halfWidth = 2;    // gaussian taps each side of the centre (2 → the seed's 5x5)
    float spacing = 1.0f; // pixels between gaussian taps
    float sharpness = 16.0f; // bilateral: relative depth difference d weighs exp(-(d * sharpness)^2)
    int passes = 2;          // bilateral: repeated edge-aware passes (XeGTAO runs 1-3)
    // bilateral: a neighbour whose AO differs by d from the pixel's weighs exp(-(d / aoSigma)^2)
    // (a range term: detail larger than the noise survives); 0 = off (depth and normal only).
    float aoSigma = 0.0f;
    DenoiseUpsample upsample = DenoiseUpsample::Joint; // reduced-resolution AO only
};

// Temporal accumulation: the denoised AO of successive frames, each with its own noise, blended
// with the previous result reprojected through the previous camera; pixels whose history does not
// match (disocclusion: another surface was there) restart.
struct TemporalSettings {
    bool enabled = false;
    int frames = 8;                // frames accumulated after a change; then the frame stays still
    // How far off this pixel's tangent plane a history texel's surface may lie and still be kept, in
    // pixel footprints (the width of one pixel at that depth): a test of the pixel's own scale.
    float planeTolerance = 1.0f;
    // While the camera moves, the history counts as at most this many frames: each frame's
    // reprojection resamples it and the view changes the AO, so a long memory lags and blurs
    // (docs/bench/temporal.md).
    int movingFrames = 2;
};

struct CompositeSettings {
    float ambient = 0.7f; // ambient strength multiplied by albedo and AO (strong: AO is what we look at)
    float light = 0.6f;   // point-light intensity (0 = AO-only shading)
    bool useAo = true;    // false: the same image without AO (N8AO-style on/off compare)
};

// Work a frame does not need, skipped; each switch exists so the saving can be measured against
// the same frame without it (`ssaolab skips`, docs/bench/skips.md). Exact: the image is the same.
struct SkipSettings {
    bool sky = true;           // AO and the denoiser's last pass return at once on sky pixels
    bool cull = true;          // G-buffer: meshes whose bounds lie outside the view are not drawn
    bool unusedTargets = true; // G-buffer: targets no pass or view reads are not written
    bool hiddenFaces = true;   // G-buffer: the hidden side of closed shells is culled (scene/closed_shells.h)
    bool occluded = true;      // G-buffer: draws the scene hides are not drawn (scene/gpu/occlusion_culler.h)
    // Reduced AO: the composite does the joint upsample itself where nothing else reads the
    // full-resolution AO (passes/composite_pass.h). Off by default: on llvmpipe it saves nothing
    // (docs/bench/skips.md).
    bool fusedUpsample = false;
    // While the camera moves (the app), the G-buffer draws a copy of a large scene with its
    // vertices clustered into cells of at most a pixel of the moving frame (scene/gpu/motion_lod.h).
    bool motionLod = true;
};

} // namespace ssao
