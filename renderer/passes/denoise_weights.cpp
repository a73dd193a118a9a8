#include "passes/denoise_weights.h"

#include <algorithm>
#include <cmath>

namespace ssao {

gpu::DenoiseConstants packDenoiseConstants(const DenoiseSettings& d, int direction, bool skipSky) {
    gpu::DenoiseConstants c{};
    int count = 0;
    if (d.kind == DenoiseKind::Box4) {
        for (int i = -2; i <= 1; ++i)
            c.offsetsWeights[count++] = {float(i), 0.25f, 0.0f, 0.0f};
    } else if (d.kind == DenoiseKind::Box4Centred) {
        // Half-texel offsets read bilinearly: each tap averages two texels, so the 4-wide box is
        // centred (weights 1/8, 1/4, 1/4, 1/4, 1/8 over -2..+2) instead of the seed's -2..+1.
        for (int i = 0; i < 4; ++i)
            c.offsetsWeights[count++] = {float(i) - 1.5f, 0.25f, 0.0f, 0.0f};
    } else if (d.kind == DenoiseKind::Gaussian) {
        const int r = d.halfWidth; // 0..32 = (SSAO_MAX_DENOISE_TAPS - 1) / 2: the table's range
        float sum = 0.0f;
        for (int i = -r; i <= r; ++i) {
            float w = std::exp(-float(i * i) / (2.0f * d.sigma * d.sigma));
            c.offsetsWeights[count++] = {float(i) * d.spacing, w, 0.0f, 0.0f};
            sum += w;
        }
        for (int i = 0; i < count; ++i)
            c.offsetsWeights[i].y /= sum;
        // Summed in float in the shader's order the normalised weights can reach 1 + 1 ulp, and an
        // AO of 1.0000001 is out of range: take any excess off the centre (largest) weight.
        float total = 0.0f;
        for (int i = 0; i < count; ++i)
            total += c.offsetsWeights[i].y;
        if (total > 1.0f) c.offsetsWeights[r].y -= total - 1.0f;
    } else {
        c.offsetsWeights[count++] = {0.0f, 1.0f, 0.0f, 0.0f};
    }
    c.taps = {count, direction, skipSky ? SSAO_DENOISE_SKIP_SKY : 0, 0};
    return c;
}

gpu::DenoiseConstants packJointUpsampleConstants() {
    gpu::DenoiseConstants c{};
    // 1 % of the depth on top of the slope's share: a curved surface's 2x2 corners stay similar,
    // an object in front of another (a gap of far more than 1 %) does not blend.
    c.taps = {4, 0, 0, 10};
    return c;
}

gpu::DenoiseConstants packBilateralConstants(const DenoiseSettings& d, bool normalUnorm, int k) {
    gpu::DenoiseConstants c{};
    // The bilateral's 2-D window is at most 17x17: a wider half-width (the gaussian's rows allow 32)
    // is the bilateral's own limit, not a range check.
    c.taps = {std::min(d.halfWidth, SSAO_BILATERAL_MAX_HALF_WIDTH), k, normalUnorm ? SSAO_DENOISE_NORMAL_UNORM : 0, 0};
    // Normal term cos^8: 0.5 at ~25 degrees, so creases split while curved surfaces stay smooth.
    // w: 1 / the AO range sigma (0: no range term).
    c.offsetsWeights[0] = {d.sigma, d.sharpness, 8.0f, d.aoSigma > 0.0f ? 1.0f / d.aoSigma : 0.0f};
    return c;
}

} // namespace ssao
