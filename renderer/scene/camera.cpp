#include "scene/camera.h"

#include "scene/scene.h"
#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace ssao {

glm::mat4 Camera::view() const {
    return glm::lookAt(eye, target, up);
}

float Camera::orthoHalfHeight() const {
    return glm::length(target - eye) * std::tan(glm::radians(fovYDeg) * 0.5f);
}

glm::mat4 Camera::projection(float aspect) const {
    const bool reversed = depth == DepthMode::Reversed;
    if (orthographic()) {
        const float h = orthoHalfHeight(), w = h * aspect;
        glm::mat4 m = glm::ortho(-w, w, -h, h, nearZ, farZ);
        if (reversed) { // z_ndc = (z_view + far) / (far - near): 1 at -near, 0 at -far
            m[2][2] = 1.0f / (farZ - nearZ);
            m[3][2] = farZ / (farZ - nearZ);
        }
        return m;
    }
    if (!reversed) return glm::perspective(glm::radians(fovYDeg), aspect, nearZ, farZ);
    // z_clip = A z_view + B, w_clip = -z_view; z_ndc = 1 at -near and 0 at -far:
    // A = n / (f - n), B = n f / (f - n); an infinite far plane is the limit A = 0, B = n.
    glm::mat4 m = glm::perspective(glm::radians(fovYDeg), aspect, nearZ, std::isinf(farZ) ? 1e30f : farZ);
    const double n = nearZ, f = farZ;
    m[2][2] = std::isinf(farZ) ? 0.0f : float(n / (f - n));
    m[3][2] = std::isinf(farZ) ? nearZ : float(n * f / (f - n));
    return m;
}

const char* projectionName(Projection p) {
    return p == Projection::Orthographic ? "orthographic" : "perspective";
}
const char* depthModeName(DepthMode d) {
    return d == DepthMode::Reversed ? "reversed" : "standard";
}
Projection parseProjection(const std::string& name) {
    if (name == "perspective") return Projection::Perspective;
    if (name == "orthographic" || name == "ortho") return Projection::Orthographic;
    throw Error("projection '" + name + "': expected perspective or orthographic");
}
DepthMode parseDepthMode(const std::string& name) {
    if (name == "standard") return DepthMode::Standard;
    if (name == "reversed" || name == "reversed-z") return DepthMode::Reversed;
    throw Error("depth '" + name + "': expected standard or reversed");
}

Camera frameBounds(const Bounds& b) {
    Camera c;
    const float r = std::max(b.radius(), 1e-3f);
    c.target = b.center();
    c.fovYDeg = 45.0f;
    const glm::vec3 dir = glm::normalize(glm::vec3(0.55f, 0.45f, 1.0f));
    // Distance at which a sphere of radius r fits the vertical field of view, plus a margin.
    const float dist = r / std::sin(glm::radians(c.fovYDeg * 0.5f)) * 1.12f;
    c.eye = c.target + dir * dist;
    c.up = {0.0f, 1.0f, 0.0f};
    c.nearZ = std::max(dist - 1.5f * r, dist * 0.01f);
    c.farZ = dist + 1.5f * r;
    return c;
}

void validateCamera(const Camera& c) {
    auto finite = [](const glm::vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(c.eye) || !finite(c.target) || !finite(c.up)) throw Error("camera: non-finite vector");
    glm::vec3 fwd = c.target - c.eye;
    if (glm::length(fwd) < 1e-12f) throw Error("camera: eye and target coincide");
    if (glm::length(glm::cross(fwd, c.up)) < 1e-9f * glm::length(fwd))
        throw Error("camera: up is parallel to the view direction");
    if (!(c.fovYDeg > 0.5f && c.fovYDeg < 179.0f)) throw Error("camera: fov must be in (0.5, 179) degrees");
    const bool infiniteFar = std::isinf(c.farZ) && c.farZ > 0.0f;
    if (infiniteFar && (c.depth != DepthMode::Reversed || c.orthographic()))
        throw Error("camera: an infinite far plane needs reversed depth and a perspective projection");
    if (!std::isfinite(c.nearZ) || !(std::isfinite(c.farZ) || infiniteFar) || !std::isfinite(c.fovYDeg))
        throw Error("camera: fov, near and far must be finite numbers");
    if (!(c.nearZ > 0.0f)) throw Error("camera: near must be > 0");
    if (!(c.farZ > c.nearZ)) throw Error("camera: far must be > near");
    if (c.depth == DepthMode::Reversed) {
        // A float holds near/z to 24 bits at any ratio - while near/z stays a normal float: past
        // 1.2e-38 it turns denormal and flushes to 0, the cleared far value, and nothing renders
        // (near 1e-38 drew an empty frame reported as "no geometry in view").
        if (c.nearZ < kMinReversedNear) {
            char buf[200];
            std::snprintf(buf, sizeof buf,
                          "camera: near = %.3g is below %.0e: reversed-Z stores depth as near/z, which leaves "
                          "float's normal range for surfaces 1e8 x near away (raise near)",
                          double(c.nearZ), double(kMinReversedNear));
            throw Error(buf);
        }
        return;
    }
    // A 32-bit depth buffer spreads its precision as near/z: past ~1e8 every surface lands on the
    // same depth value and nothing renders (near 1e-9, far 1e9 gave an empty frame reported as
    // "fully occluded"). 2CylinderEngine's own camera (0.05 .. 1e6, 2e7) still passes.
    if (double(c.farZ) / double(c.nearZ) > kMaxFarNearRatio) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "camera: far/near = %.3g exceeds %.0e: the depth buffer cannot resolve it "
                      "(raise near, fit the planes to the scene, or use reversed depth)", double(c.farZ) / double(c.nearZ), kMaxFarNearRatio);
        throw Error(buf);
    }
}

Camera parseCamera(const std::string& text, const Camera& base, const glm::dvec3& origin) {
    std::vector<double> v;
    std::stringstream ss(text);
    std::string tok;
    while (std::getline(ss, tok, ',')) {
        double d = 0;
        if (v.size() == 11 && (tok == "inf" || tok == "infinity")) { // an infinite far plane
            v.push_back(INFINITY);
            continue;
        }
        if (!parseDecimal(tok, d)) throw Error("--camera: '" + tok + "' is not a number");
        if (!std::isfinite(float(d))) throw Error("--camera: '" + tok + "' is not a finite number");
        v.push_back(d);
    }
    if (!(v.size() == 6 || v.size() == 9 || v.size() == 10 || v.size() == 12))
        throw Error(
            "--camera: expected 6, 9, 10 or 12 numbers (eye, target[, up[, fov[, near, far]]]), got " +
            std::to_string(v.size()));
    Camera c = base;
    c.eye = glm::vec3(glm::dvec3(v[0], v[1], v[2]) - origin);
    c.target = glm::vec3(glm::dvec3(v[3], v[4], v[5]) - origin);
    if (v.size() >= 9) c.up = glm::vec3(v[6], v[7], v[8]);
    if (v.size() >= 10) c.fovYDeg = float(v[9]);
    if (v.size() >= 12) { // explicit planes are used as given
        c.nearZ = float(v[10]);
        c.farZ = float(v[11]);
        c.clip = ClipMode::Fixed;
    }
    validateCamera(c);
    return c;
}

} // namespace ssao
