// Scenes with closed-form AO for the reference and the screen-space oracle: a floor, a wall
// beside it, cameras looking at them, and the floor-beside-a-wall integral.
#pragma once
#include "scene/camera.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace ssaotest {

using ssao::Camera;
using ssao::ClipMode;
using ssao::Scene;

inline void quad(Scene& s, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
    const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p3 - p0));
    const uint32_t b = uint32_t(s.vertices.size());
    for (auto& p : {p0, p1, p2, p3})
        s.vertices.push_back({p, n});
    s.indices.insert(s.indices.end(), {b, b + 1, b + 2, b, b + 2, b + 3});
}

// A closed box [lo, hi] wound counter-clockwise seen from outside (glTF's front faces).
inline void box(Scene& s, glm::vec3 lo, glm::vec3 hi) {
    const float x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
    quad(s, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}); // +y
    quad(s, {x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}); // -y
    quad(s, {x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}); // +x
    quad(s, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}); // -x
    quad(s, {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}); // +z
    quad(s, {x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}); // -z
}

// Floor y = 0 over [-L, L]^2, optionally a wall x = 0 (facing +x) of height H.
inline Scene floorScene(bool wall, float L = 50.0f, float H = 50.0f) {
    Scene s;
    s.name = "floor";
    quad(s, {-L, 0, -L}, {-L, 0, L}, {L, 0, L}, {L, 0, -L});
    if (wall) quad(s, {0, 0, -L}, {0, H, -L}, {0, H, L}, {0, 0, L});
    s.draws.push_back({0, uint32_t(s.indices.size()), glm::vec4(1)});
    s.computeBounds();
    return s;
}

inline Camera lookDown(glm::vec3 at, float height, float fov = 60.0f) {
    Camera c;
    c.eye = at + glm::vec3(0, height, 0);
    c.target = at;
    c.up = {0, 0, -1};
    c.fovYDeg = fov;
    c.nearZ = 0.01f;
    c.farZ = 1000.0f;
    c.clip = ClipMode::Fixed;
    return c;
}

// World position of a pixel's primary hit, from the reference's own depth.
inline glm::vec3 hitPosition(const Camera& c, int w, int h, int x, int y, float depth) {
    const glm::vec3 fwd = glm::normalize(c.target - c.eye);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, c.up));
    const glm::vec3 up = glm::cross(right, fwd);
    const float t = std::tan(glm::radians(c.fovYDeg) * 0.5f);
    const float nx = 2.0f * (x + 0.5f) / w - 1.0f, ny = 1.0f - 2.0f * (y + 0.5f) / h;
    const glm::vec3 viewDir = fwd + right * (nx * t * float(w) / h) + up * (ny * t); // unit depth
    return c.eye + viewDir * depth;
}

// AO of a floor point at distance d from an infinite wall (cosine-weighted, within R).
inline double wallClosedForm(double d, double R) {
    const double a = std::min(d / R, 1.0);
    return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / M_PI;
}


} // namespace ssaotest
