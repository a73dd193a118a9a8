// Robust secondary-ray origins: Wächter & Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6 (2019) — the offset XeGTAO's reference uses. The
// origin moves along the geometric normal by a few float ULPs of the position (integer offset),
// or by a tiny fixed amount near the origin where ULPs vanish. Being relative to the position's
// own precision, it never pushes a point in a crease through the neighbouring wall (a fixed
// epsilon that is safe far from the origin would be millimetres there).
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
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

// How far a primary hit moves back toward the eye before the offset above, in float ULPs of the
// largest coordinate of its triangle. A pixel centre that lands on a crease where two solids pass
// through each other (CornellBox's wall slabs) gives a hit that lies, by a rounding error of a ULP
// or two, inside the other solid; the offset along this face's normal runs parallel to the other
// face and cannot get out, so every AO ray starts inside and hits (AO 0 instead of the crease's
// 0.5). The segment from the eye to the hit crosses no surface (it is the primary ray), so a point
// slightly before the hit lies outside every solid; 256 ULPs beat the rounding unless the other face
// is seen within about half a degree of edge-on, and are ~3e-5 of the coordinates: far below R.
constexpr float kBackOffUlps = 256.0f;

// `scale`: the largest |coordinate| of the hit's triangle (its vertices' float precision).
inline glm::vec3 backOffTowardEye(const glm::vec3& p, const glm::vec3& towardEye, float scale) {
    const float ulp = std::max(scale, 1e-30f) * 0x1p-23f; // float spacing at `scale` (within 2x)
    return p + towardEye * (kBackOffUlps * ulp);
}

// A surface closer to the offset origin than this many ULPs (of the hit's coordinates or of the
// primary ray's length, whichever is coarser) lies where the hit itself is, to within rounding:
// coincident faces (a CAD solid's face drawn twice, two tessellations of one surface). Which of
// them the primary ray hits, and so whether the other occludes every AO ray, is decided by
// rounding, not by geometry.
constexpr float kCoincidentUlps = 64.0f;

inline float coincidenceDistance(float scale) {
    return kCoincidentUlps * std::max(scale, 1e-30f) * 0x1p-23f;
}

} // namespace ssao
