#include "techniques/kernel/pack.h"

#include "techniques/kernel/sampling.h"


namespace ssao {

gpu::KernelConstants packKernelConstants(const KernelSettings& s, const gpu::AoCommon& common) {
    gpu::KernelConstants c{};
    c.aoCommon = common;
    const int n = s.samples; // 1..KERNEL_MAX_SAMPLES: the parameter table's range
    // The |dz| floor keeps radius/|dz| finite when the depths are equal (0/0 → NaN as radius → 0).
    c.params = {s.bias, 1e-4f, 0.0f, 0.0f};
    c.noiseScale = {common.target.x / 4.0f, common.target.y / 4.0f, 0.0f, 0.0f};
    int flags = 0;
    if (s.separable) flags |= KERNEL_FLAG_SEPARABLE;
    if (s.noise == Noise::Tex4x4) flags |= KERNEL_FLAG_NOISE;
    if (s.positionSource == PositionSource::Depth) flags |= KERNEL_FLAG_POS_FROM_DEPTH;
    if (s.offscreen == Offscreen::Clamp) flags |= KERNEL_FLAG_OFFSCREEN_CLAMP;
    if (s.ownTexel == OwnTexel::Open) flags |= KERNEL_FLAG_OWN_TEXEL_OPEN;
    const int range = s.rangeCheck == RangeCheck::Smoothstep ? KERNEL_RANGE_SMOOTHSTEP
                      : s.rangeCheck == RangeCheck::Hard     ? KERNEL_RANGE_HARD
                                                             : KERNEL_RANGE_OFF;
    const int depthTest =
        s.depthTest == DepthTest::Sample ? KERNEL_DEPTHTEST_SAMPLE : KERNEL_DEPTHTEST_FRAGMENT;
    c.modes = {n, range, depthTest, flags};

    const uint32_t seed = uint32_t(s.seed);
    std::vector<glm::vec3> a, b;
    if (s.separable) {
        a = makeKernel(SampleSet::PlaneXZ, n, seed);
        b = makeKernel(SampleSet::PlaneYZ, n, seed);
        // The sphere option applies to the plane sets too: mirror z to [-1,1] on alternate samples.
        if (s.shape == KernelShape::Sphere)
            for (int i = 0; i < n; i += 2)
                a[size_t(i)].z = -a[size_t(i)].z, b[size_t(i)].z = -b[size_t(i)].z;
    } else {
        a = makeKernel(s.shape == KernelShape::Sphere ? SampleSet::Sphere : SampleSet::Hemisphere, n, seed);
    }
    for (int i = 0; i < n; ++i)
        c.kernel[i] = glm::vec4(a[size_t(i)], 0.0f);
    for (int i = 0; i < int(b.size()); ++i)
        c.kernel[KERNEL_MAX_SAMPLES + i] = glm::vec4(b[size_t(i)], 0.0f);
    return c;
}

} // namespace ssao
