#include "techniques/sao/pack.h"

namespace ssao {

gpu::SaoConstants packSaoConstants(const SaoSettings& s, const gpu::AoCommon& common) {
    gpu::SaoConstants c{};
    c.aoCommon = common;
    // x: turns, y: 2σ/N (Alchemy's normalisation), z: β, w: ε (SAO's 0.01, in units of R²).
    c.params = {s.turns, 2.0f * s.intensity / float(s.samples), s.bias, 0.01f};
    c.modes = {s.samples, 0, 0, 0};
    return c;
}

} // namespace ssao
