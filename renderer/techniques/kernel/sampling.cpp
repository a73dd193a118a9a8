#include "techniques/kernel/sampling.h"

#include <cmath>

namespace ssao {

float kernelScale(int i, int n) {
    float t = float(i) / float(n);
    return 0.1f + 0.9f * t * t; // lerp(0.1, 1, t²): more samples close to the pixel
}

std::vector<glm::vec3> makeKernel(SampleSet shape, int n, uint32_t seed) {
    Rng rng(uint64_t(seed) * 4 + uint64_t(shape));
    std::vector<glm::vec3> k;
    k.reserve(size_t(n));
    for (int i = 0; i < n; ++i) {
        glm::vec3 v;
        do { // a zero-length draw has no direction: draw again (the seeds would normalise 0 → NaN)
            float x = rng.uniform(-1.0f, 1.0f), y = rng.uniform(-1.0f, 1.0f);
            float zh = rng.uniform(0.0f, 1.0f), zs = rng.uniform(-1.0f, 1.0f);
            switch (shape) {
            case SampleSet::Hemisphere:
                v = {x, y, zh};
                break;
            case SampleSet::Sphere:
                v = {x, y, zs};
                break;
            case SampleSet::PlaneXZ:
                v = {x, 0.0f, zh};
                break;
            case SampleSet::PlaneYZ:
                v = {0.0f, y, zh};
                break;
            }
        } while (glm::dot(v, v) < 1e-8f);
        v = glm::normalize(v) * rng.uniform(); // uniform length in [0,1) ...
        k.push_back(v * kernelScale(i, n));    // ... pulled towards the centre
    }
    return k;
}

std::vector<glm::vec3> makeNoise(uint32_t seed) {
    Rng rng(uint64_t(seed) * 4 + 7);
    std::vector<glm::vec3> out;
    while (out.size() < 16) {
        // Named draws: a constructor's arguments are evaluated in no fixed order, and the tile
        // (and the learnopengl example that rebuilds it) must not change with the compiler.
        const float y = rng.uniform(-1.0f, 1.0f), x = rng.uniform(-1.0f, 1.0f);
        const glm::vec3 v(x, y, 0.0f);
        if (glm::dot(v, v) > 1e-4f) out.push_back(v);
    }
    return out;
}

glm::mat3 tangentFrame(const glm::vec3& n, const glm::vec3& r) {
    glm::vec3 t = r - n * glm::dot(r, n);
    float len2 = glm::dot(t, t);
    if (len2 > 1e-6f) {
        t /= std::sqrt(len2);
    } else {
        // Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin: "Building an Orthonormal
        // Basis, Revisited", JCGT 6(1), 2017, listing 3.
        float sgn = std::copysign(1.0f, n.z);
        float a = -1.0f / (sgn + n.z);
        float b = n.x * n.y * a;
        t = glm::vec3(1.0f + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
    }
    glm::vec3 bt = glm::cross(n, t);
    return glm::mat3(t, bt, n);
}

} // namespace ssao
