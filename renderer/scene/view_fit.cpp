#include "scene/view_fit.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace ssao {

std::pair<float, float> depthRange(const Camera& c, const Bounds& b) {
    const glm::vec3 fwd = glm::normalize(c.target - c.eye);
    float zmin = INFINITY, zmax = -INFINITY;
    for (int i = 0; i < 8; ++i) {
        const float z = glm::dot(b.corner(i) - c.eye, fwd);
        zmin = std::min(zmin, z);
        zmax = std::max(zmax, z);
    }
    return {zmin, zmax};
}

std::pair<float, float> depthRange(const glm::mat4& view, const Bounds& b) {
    float zmin = INFINITY, zmax = -INFINITY;
    for (int i = 0; i < 8; ++i) {
        const float z = -(view * glm::vec4(b.corner(i), 1.0f)).z;
        zmin = std::min(zmin, z);
        zmax = std::max(zmax, z);
    }
    return {zmin, zmax};
}

std::pair<float, float> fitClipPlanes(const Camera& c, const Bounds& b) {
    const auto [zmin, zmax] = depthRange(c, b);
    const float size = std::max(b.radius(), 1e-6f);
    // The whole scene is behind the camera: any valid planes will do, nothing is visible.
    if (!(zmax > 0.0f)) return {size * 1e-3f, size};
    const float far = zmax * 1.02f + size * 1e-4f;
    // 1e4 keeps the depth test's resolution below ~1e-3 of far even for a camera inside the bounds.
    const float near = std::max(zmin * 0.98f, far * 1e-4f);
    return {near, far};
}

Camera effectiveCamera(const Camera& c, const Bounds& b) {
    if (c.clip != ClipMode::Fit || !b.valid()) return c;
    Camera e = c;
    std::tie(e.nearZ, e.farZ) = fitClipPlanes(c, b);
    return e;
}

std::optional<float> firstHit(const Scene& s, const glm::vec3& o, const glm::vec3& d) {
    // Möller–Trumbore, 1997, over every triangle.
    float best = INFINITY;
    for (size_t t = 0; t + 2 < s.indices.size(); t += 3) {
        const glm::vec3& a = s.vertices[s.indices[t]].position;
        const glm::vec3 e1 = s.vertices[s.indices[t + 1]].position - a;
        const glm::vec3 e2 = s.vertices[s.indices[t + 2]].position - a;
        const glm::vec3 p = glm::cross(d, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-20f) continue;
        const float inv = 1.0f / det;
        const glm::vec3 q = o - a;
        const float u = glm::dot(q, p) * inv;
        if (u < 0.0f || u > 1.0f) continue;
        const glm::vec3 r = glm::cross(q, e1);
        const float v = glm::dot(d, r) * inv;
        if (v < 0.0f || u + v > 1.0f) continue;
        const float dist = glm::dot(e2, r) * inv;
        if (dist > 0.0f && dist < best) best = dist;
    }
    if (!std::isfinite(best)) return std::nullopt;
    return best;
}

void placeOrbitTarget(Camera& c, const Scene& s) {
    const glm::vec3 fwd = glm::normalize(c.target - c.eye);
    const float r = std::max(s.bounds.radius(), 1e-6f);
    float dist = glm::dot(s.bounds.center() - c.eye, fwd);
    if (!(dist > 1e-3f * r)) dist = firstHit(s, c.eye, fwd).value_or(r);
    c.target = c.eye + fwd * dist;
}

} // namespace ssao
