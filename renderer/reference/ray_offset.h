// Robust secondary-ray origins: Wächter & Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6 (2019) — the offset XeGTAO's reference uses. The
// origin moves along the geometric normal by a few float ULPs of the position (integer offset),
// or by a tiny fixed amount near the origin where ULPs vanish. Being relative to the position's
// own precision, it never pushes a point in a crease through the neighbouring wall (a fixed
// epsilon that is safe far from the origin would be millimetres there).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <cstring>

namespace ssao {

inline glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n) {
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    glm::vec3 out;
    for (int a = 0; a < 3; ++a) {
        const int32_t of = int32_t(kIntScale * n[a]);
        int32_t bits;
        std::memcpy(&bits, &p[a], 4);
        bits += (p[a] < 0.0f) ? -of : of;
        float moved;
        std::memcpy(&moved, &bits, 4);
        out[a] = std::abs(p[a]) < kOrigin ? p[a] + kFloatScale * n[a] : moved;
    }
    return out;
}

} // namespace ssao
