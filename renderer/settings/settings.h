// What a person sets (units, meaning) — not what the GPU sees: see ssao/constants.h for the
// packing. Defaults and ranges live in the parameter table (settings/params.cpp), the one place
// that feeds presets, --set, the UI and the tests.
#pragma once

namespace ssao {

enum class TargetFormat { RGBA16F = 0, RGBA32F = 1, RGBA8 = 2 }; // RGBA8: normals only, (n+1)/2
enum class Kernel { Hemisphere = 0, Sphere = 1 };                // sphere = Crytek 2007
enum class RangeCheck { Smoothstep = 0, Hard = 1, Off = 2 };
enum class DepthTest { Sample = 0, Fragment = 1 }; // see bindings.h
enum class Noise { Tex4x4 = 0, None = 1 };
enum class PositionSource { GBuffer = 0, Depth = 1 };
enum class Offscreen { Skip = 0, Clamp = 1 };
enum class BlurKind { None = 0, Box4 = 1, Gaussian = 2 };

struct GBufferSettings {
    TargetFormat positionFormat = TargetFormat::RGBA32F;
    TargetFormat normalFormat = TargetFormat::RGBA16F;
};

struct SsaoSettings {
    Kernel kernel = Kernel::Hemisphere;
    bool separable = false; // seed 003: two plane-sample sets, normalised by 2N
    int samples = 64;       // per set
    float radius = 0.5f;    // view-space units (scene units)
    float bias = 0.025f;    // view-space units
    RangeCheck rangeCheck = RangeCheck::Smoothstep;
    DepthTest depthTest = DepthTest::Sample;
    float power = 1.0f; // AO = visibility^power (>1 darkens)
    Noise noise = Noise::Tex4x4;
    int seed = 0; // kernel + noise RNG seed
    PositionSource positionSource = PositionSource::GBuffer;
    Offscreen offscreen = Offscreen::Skip;
};

struct BlurSettings {
    BlurKind kind = BlurKind::Box4;
    float sigma = 1.5f;   // gaussian standard deviation, in taps
    int radius = 2;       // gaussian half-width in taps (2 → 5x5)
    float spacing = 1.0f; // pixels between taps
};

struct CompositeSettings {
    float ambient = 0.7f; // ambient strength multiplied by albedo and AO (strong: AO is what we look at)
    float light = 0.6f;   // point-light intensity (0 = AO-only shading)
    bool useAo = true;    // false: the same image without SSAO (N8AO-style AO on/off compare)
};

struct Settings {
    GBufferSettings gbuffer;
    SsaoSettings ssao;
    BlurSettings blur;
    CompositeSettings composite;
};

} // namespace ssao
