#include "scene/gpu/motion_lod.h"

#include "scene/view_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace ssao {

namespace {
constexpr uint64_t kAxisCells = uint64_t(1) << 19;

// Which of 24 cones a normal lies in: its octant and its largest axis (the cube face the octant's
// part of the sphere falls on). Normals more than ~70 degrees apart never share one.
uint64_t normalBucket(const glm::vec3& n) {
    const glm::vec3 a = glm::abs(n);
    const uint64_t axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return axis << 3 | uint64_t(n.x < 0.0f) | uint64_t(n.y < 0.0f) << 1 | uint64_t(n.z < 0.0f) << 2;
}

// Cell of p (19 bits an axis) and the cone of its normal (5 bits): one 62-bit key.
uint64_t cellKey(const Vertex& v, const glm::vec3& origin, float cell) {
    uint64_t key = 0;
    for (int a = 0; a < 3; ++a) {
        const float c = std::floor((v.position[a] - origin[a]) / cell);
        // Clamped as a float first: a float past 2^64 has no uint64_t (NaN lands in cell 0).
        const uint64_t i = c > 0.0f ? uint64_t(std::min(c, float(kAxisCells - 1))) : 0;
        key = (key << 19) | i;
    }
    return (key << 5) | normalBucket(v.normal);
}

struct TriangleHash {
    size_t operator()(const std::array<uint32_t, 3>& t) const {
        return size_t((uint64_t(t[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(t[1]) * 0xC2B2AE3D27D4EB4Full) ^
                      (uint64_t(t[2]) * 0x165667B19E3779F9ull));
    }
};
} // namespace

MotionLod buildMotionLod(const Scene& scene, float cell) {
    MotionLod lod;
    if (!(cell > 0.0f) || !std::isfinite(cell)) return lod;
    lod.cell = cell;
    lod.indices.reserve(scene.indices.size() / 2);
    const glm::vec3 origin = scene.bounds.valid() ? scene.bounds.min : glm::vec3(0.0f);
    std::unordered_map<uint64_t, uint32_t> representative;
    std::unordered_map<uint32_t, uint32_t> mapped; // vertex -> its cell's representative, this draw
    std::unordered_set<std::array<uint32_t, 3>, TriangleHash> seen;
    for (const Draw& d : scene.draws) {
        lod.first.push_back(uint32_t(lod.indices.size()));
        const size_t triangles = d.indexCount / 3;
        if (d.mask) { // kept whole: a cut-out's edge follows its texture, not its vertices
            lod.indices.insert(lod.indices.end(), scene.indices.begin() + d.firstIndex,
                               scene.indices.begin() + d.firstIndex + 3 * triangles);
            lod.count.push_back(uint32_t(3 * triangles));
            continue;
        }
        representative.clear(), mapped.clear(), seen.clear();
        auto rep = [&](uint32_t v) {
            auto it = mapped.find(v);
            if (it != mapped.end()) return it->second;
            const uint32_t r = representative.emplace(cellKey(scene.vertices[v], origin, cell), v).first->second;
            mapped.emplace(v, r);
            return r;
        };
        for (size_t t = 0; t < triangles; ++t) {
            const uint32_t* idx = scene.indices.data() + d.firstIndex + 3 * t;
            const uint32_t a = rep(idx[0]), b = rep(idx[1]), c = rep(idx[2]);
            if (a == b || b == c || a == c) continue; // collapsed into a line or a point
            std::array<uint32_t, 3> key{a, b, c};
            std::sort(key.begin(), key.end());
            if (!seen.insert(key).second) continue; // the same three corners again
            lod.indices.insert(lod.indices.end(), {a, b, c});
        }
        lod.count.push_back(uint32_t(lod.indices.size()) - lod.first.back());
    }
    return lod;
}

std::vector<MotionLod> motionLodsFor(const Scene& scene) {
    std::vector<MotionLod> out;
    if (scene.triangleCount() < kMotionLodMinTriangles || !scene.bounds.valid()) return out;
    const float diagonal = 2.0f * scene.bounds.radius();
    for (const float cells : kMotionLodCellsPerDiagonal) {
        MotionLod lod = buildMotionLod(scene, diagonal / cells);
        if (lod.cell == 0.0f || double(lod.triangles()) > 0.75 * double(scene.triangleCount())) break;
        out.push_back(std::move(lod));
    }
    return out;
}

float motionLodCellPx(float cell, const Bounds& bounds, const glm::mat4& view, float projY, bool orthographic,
                      int height) {
    const float inf = std::numeric_limits<float>::infinity();
    if (!bounds.valid() || height <= 0 || !(projY > 0.0f)) return inf;
    // A cell at depth d spans cell * projY / d of the frame's height of 2 (NDC), so cell * projY *
    // height / (2 d) pixels; orthographic: d = 1.
    if (orthographic) return cell * projY * float(height) * 0.5f;
    // The box's least depth along the view axis: no surface in it lies nearer to the image plane
    // (with the screen-edge stretch of a wide lens, a cell may reach ~1/cos^2 of this there).
    const auto [distance, farthest] = depthRange(view, bounds);
    if (farthest <= 0.0f) return 0.0f; // behind the camera
    if (!(distance > 0.0f)) return inf;
    return cell * projY * float(height) / (2.0f * distance);
}

float motionLodCellPx(float cell, const Bounds& bounds, const Camera& camera, int height) {
    const float projY = camera.orthographic() ? 1.0f / camera.orthoHalfHeight()
                                              : 1.0f / std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    return motionLodCellPx(cell, bounds, camera.view(), projY, camera.orthographic(), height);
}

} // namespace ssao
