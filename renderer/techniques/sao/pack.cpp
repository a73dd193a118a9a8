#include "techniques/sao/pack.h"

#include <algorithm>

namespace ssao {

gpu::SaoConstants packSaoConstants(const SaoSettings& s, const gpu::AoCommon& common, bool normalUnorm) {
    gpu::SaoConstants c{};
    c.aoCommon = common;
    const int n = std::clamp(s.samples, 1, SAO_MAX_SAMPLES);
    // x: turns, y: 2σ/N (Alchemy's normalisation), z: β, w: ε (SAO's 0.01, in units of R²).
    c.params = {std::max(s.turns, 0.0f), 2.0f * std::max(s.intensity, 0.0f) / float(n),
                std::clamp(s.bias, 0.0f, 1.0f), 0.01f};
    int flags = 0;
    packNoise(c.aoCommon, s.noise);
    c.aoCommon.shape.w = s.pyramid ? 3.0f : 0.0f; // taps d px away read MIP log2(d) - this (SAO LOG_MAX_OFFSET)
    if (s.noise != AoNoise::None) flags |= SAO_FLAG_NOISE;
    if (normalUnorm) flags |= SAO_FLAG_NORMAL_UNORM;
    c.modes = {n, flags, 0, 0};
    return c;
}

} // namespace ssao
