// CPU side of kernel SSAO's sampling: kernels (seeds 000/004, Crytek, seed 003's plane sets),
// rotation noise, and the orthonormal basis the shader builds (mirrored here for tests).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ssao {

// Deterministic across platforms (std:: distributions are not): SplitMix64 → [0,1).
class Rng {
  public:
    explicit Rng(uint64_t seed) : s_(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
    float uniform() { // [0, 1) with 24 random bits
        return float(next() >> 40) * (1.0f / 16777216.0f);
    }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    uint64_t next() {
        uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

  private:
    uint64_t s_;
};

enum class SampleSet {
    Hemisphere, // x,y in [-1,1], z in [0,1]     (seeds 000/004)
    Sphere,     // x,y,z in [-1,1]               (Crytek 2007: flat surfaces ≈ 50 % occluded)
    PlaneXZ,    // y = 0, z in [0,1]             (seed 003 separable, x set)
    PlaneYZ,    // x = 0, z in [0,1]             (seed 003 separable, y set)
};

// The lerp(0.1, 1, (i/N)^2) scale of seed 000/004: sample i lies within this radius.
float kernelScale(int i, int n);

// N samples inside the unit ball (or half-ball), tangent space, z = normal direction.
std::vector<glm::vec3> makeKernel(SampleSet shape, int n, uint32_t seed);

// 16 rotation vectors (x,y uniform in [-1,1], z = 0) for the 4x4 tile; never near zero length.
std::vector<glm::vec3> makeNoise(uint32_t seed);

// Tangent frame around unit normal n, rotated by the random vector r (Gram–Schmidt as in the
// seeds), falling back to Duff et al. 2017's branchless basis when r is (nearly) parallel to
// n or zero — the case where the seeds' normalize(0) returns NaN. Columns: t, b, n.
glm::mat3 tangentFrame(const glm::vec3& n, const glm::vec3& r);

} // namespace ssao
