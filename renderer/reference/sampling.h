// Low-discrepancy sample generation for the reference tracer: Owen-scrambled, shuffled 2D Sobol
// points (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4)), seeded per pixel, so a
// pixel's sample i is the same whichever thread, pass or batch traces it. Pure, header-only.
#pragma once
#include <cmath>
#include <cstdint>

namespace ssao::sampling {

inline uint32_t reverseBits(uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// Laine-Karras style hash (Vegdahl's 2021 constants, better mixing than Burley's originals): every
// step only lets lower bits change higher ones, so applied to bit-reversed values it is a nested
// uniform (Owen) scramble.
inline uint32_t laineKarras(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
    return reverseBits(laineKarras(reverseBits(x), seed));
}

// 32-bit integer hash (Wellons' lowbias32): decorrelates seeds of neighbouring pixels.
inline uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

inline uint32_t hashCombine(uint32_t seed, uint32_t v) {
    return seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2));
}

// Sobol dimensions 0 (van der Corput in base 2) and 1 (primitive polynomial x + 1: direction
// numbers v_k = v_{k-1} ^ (v_{k-1} >> 1), v_0 = 2^31).
inline uint32_t sobol0(uint32_t i) { return reverseBits(i); }
inline uint32_t sobol1(uint32_t i) {
    uint32_t r = 0, v = 1u << 31;
    for (; i; i >>= 1, v ^= v >> 1)
        if (i & 1u) r ^= v;
    return r;
}

struct Sample2 {
    float u, v; // in [0, 1)
};

// The i-th point of a pixel's sequence (seed = the pixel's seed): shuffle the index, then scramble
// each dimension with its own seed (Burley 2020, listing 5).
inline Sample2 sobol2D(uint32_t i, uint32_t seed) {
    const uint32_t idx = owenScramble(i, seed);
    const uint32_t x = owenScramble(sobol0(idx), hashCombine(seed, 0xa511e9b3u));
    const uint32_t y = owenScramble(sobol1(idx), hashCombine(seed, 0x63d83595u));
    // 24 high bits → exact floats strictly below 1.
    return {float(x >> 8) * 0x1p-24f, float(y >> 8) * 0x1p-24f};
}

// Malley's method: a uniform disc point lifted to the hemisphere gives pdf cos(theta)/pi about +z.
// Returns the local direction (x, y, z), z = cos(theta) >= 0.
inline void cosineHemisphere(Sample2 s, float& x, float& y, float& z) {
    const float r = std::sqrt(s.u);
    const float phi = 6.28318530717958647692f * s.v;
    x = r * std::cos(phi);
    y = r * std::sin(phi);
    z = std::sqrt(std::fmax(0.0f, 1.0f - s.u));
}

} // namespace ssao::sampling
