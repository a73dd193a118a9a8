// Kernel SSAO as the seed articles describe it (Crytek 2007, Chapman 2013 / LearnOpenGL, seeds
// 000–004): N samples in a kernel around the pixel, each tested against the depth buffer.
// Radius and power are shared by every technique (AoSettings).
#pragma once

namespace ssao {

enum class KernelShape { Hemisphere, Sphere }; // sphere = Crytek 2007 (flat surfaces ≈ 50 % occluded)
enum class RangeCheck { Smoothstep, Hard, Off };
enum class DepthTest { Sample, Fragment };
enum class Noise { Tex4x4, None };
enum class PositionSource { GBuffer, Depth };
enum class Offscreen { Skip, Clamp };
enum class OwnTexel { Open, Test }; // a sample reading its own pixel's texel: open, or tested (the seeds)

struct KernelSettings {
    KernelShape shape = KernelShape::Hemisphere;
    bool separable = false; // seed 003: two plane-sample sets, normalised by 2N
    int samples = 64;       // per set
    float bias = 0.05f;     // fraction of the radius (LearnOpenGL: 0.025 at radius 0.5)
    RangeCheck rangeCheck = RangeCheck::Smoothstep;
    DepthTest depthTest = DepthTest::Sample;
    Noise noise = Noise::Tex4x4;
    int seed = 0; // kernel + noise RNG seed
    PositionSource positionSource = PositionSource::GBuffer;
    Offscreen offscreen = Offscreen::Skip;
    OwnTexel ownTexel = OwnTexel::Open;
};

} // namespace ssao
