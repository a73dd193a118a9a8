#include "ssao/constants.h"

#include "ssao/kernel.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace ssao {

gpu::FrameConstants packFrameConstants(const Camera& cam, int width, int height, float sceneRadius) {
    gpu::FrameConstants f{};
    f.view = cam.view();
    f.proj = cam.projection(float(width) / float(height));
    f.invProj = glm::inverse(f.proj);
    f.viewport = {float(width), float(height), 1.0f / float(width), 1.0f / float(height)};
    f.clip = {cam.nearZ, cam.farZ, sceneRadius, 0.0f};
    return f;
}

gpu::SsaoConstants packSsaoConstants(const SsaoSettings& s, const GBufferSettings& g, int width, int height) {
    gpu::SsaoConstants c{};
    const int n = std::clamp(s.samples, 1, SSAO_MAX_SAMPLES);
    // rangeEpsilon keeps radius/|dz| finite when the depths are equal (0/0 → NaN when radius→0).
    c.params0 = {s.radius, s.bias, s.power, 1e-4f * s.radius};
    c.noiseScale = {float(width) / 4.0f, float(height) / 4.0f, 0.0f, 0.0f};
    int flags = 0;
    if (s.separable) flags |= SSAO_FLAG_SEPARABLE;
    if (s.noise == Noise::Tex4x4) flags |= SSAO_FLAG_NOISE;
    if (s.positionSource == PositionSource::Depth) flags |= SSAO_FLAG_POS_FROM_DEPTH;
    if (s.offscreen == Offscreen::Clamp) flags |= SSAO_FLAG_OFFSCREEN_CLAMP;
    if (g.normalFormat == TargetFormat::RGBA8) flags |= SSAO_FLAG_NORMAL_UNORM;
    const int range = s.rangeCheck == RangeCheck::Smoothstep ? SSAO_RANGE_SMOOTHSTEP
                      : s.rangeCheck == RangeCheck::Hard     ? SSAO_RANGE_HARD
                                                             : SSAO_RANGE_OFF;
    const int depthTest = s.depthTest == DepthTest::Sample ? SSAO_DEPTHTEST_SAMPLE : SSAO_DEPTHTEST_FRAGMENT;
    c.modes = {n, range, depthTest, flags};

    const uint32_t seed = uint32_t(s.seed);
    std::vector<glm::vec3> a, b;
    if (s.separable) {
        a = makeKernel(KernelShape::PlaneXZ, n, seed);
        b = makeKernel(KernelShape::PlaneYZ, n, seed);
        // The sphere option applies to the plane sets too: mirror z to [-1,1] on alternate samples.
        if (s.kernel == Kernel::Sphere)
            for (int i = 0; i < n; i += 2)
                a[size_t(i)].z = -a[size_t(i)].z, b[size_t(i)].z = -b[size_t(i)].z;
    } else {
        a = makeKernel(s.kernel == Kernel::Sphere ? KernelShape::Sphere : KernelShape::Hemisphere, n, seed);
    }
    for (int i = 0; i < n; ++i)
        c.kernel[i] = glm::vec4(a[size_t(i)], 0.0f);
    for (int i = 0; i < int(b.size()); ++i)
        c.kernel[SSAO_MAX_SAMPLES + i] = glm::vec4(b[size_t(i)], 0.0f);
    return c;
}

gpu::BlurConstants packBlurConstants(const BlurSettings& b, int direction) {
    gpu::BlurConstants c{};
    int count = 0;
    if (b.kind == BlurKind::Box4) {
        for (int i = -2; i <= 1; ++i)
            c.offsetsWeights[count++] = {float(i), 0.25f, 0.0f, 0.0f};
    } else if (b.kind == BlurKind::Gaussian) {
        const int r = std::clamp(b.radius, 0, (SSAO_MAX_BLUR_TAPS - 1) / 2);
        float sum = 0.0f;
        for (int i = -r; i <= r; ++i) {
            float w = std::exp(-float(i * i) / (2.0f * b.sigma * b.sigma));
            c.offsetsWeights[count++] = {float(i) * b.spacing, w, 0.0f, 0.0f};
            sum += w;
        }
        for (int i = 0; i < count; ++i)
            c.offsetsWeights[i].y /= sum;
    } else {
        c.offsetsWeights[count++] = {0.0f, 1.0f, 0.0f, 0.0f};
    }
    c.taps = {count, direction, 0, 0};
    return c;
}

} // namespace ssao
