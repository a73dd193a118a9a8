// A tileable blue-noise texture made at start-up by Ulichney's void-and-cluster method (1993):
// every value 0..n²-1 appears once (a uniform histogram), and neighbouring ranks lie far apart, so
// the noise has little low-frequency energy and a small blur removes it (what the denoiser does).
// Pure and deterministic (fixed seed); tested in tests/cpu/test_noise.cpp.
#pragma once
#include <cstdint>
#include <vector>

namespace ssao {

// Ranks 0..size²-1, row-major, of a size x size toroidal void-and-cluster pattern (Gaussian energy
// filter of σ = 1.5 pixels, Ulichney's choice). `seed` picks the initial random pattern.
std::vector<uint32_t> voidAndCluster(int size, uint32_t seed);

// The texture the shaders read (SSAO_TEX_BLUE_NOISE): 64x64, two independent patterns as
// (rank + 0.5) / 4096 in r and g. Computed once per process.
const std::vector<float>& blueNoise64Rg();
constexpr int kBlueNoiseSize = 64;

} // namespace ssao
