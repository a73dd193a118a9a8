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

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fovYDeg), aspect, nearZ, farZ);
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
    if (!std::isfinite(c.nearZ) || !std::isfinite(c.farZ) || !std::isfinite(c.fovYDeg))
        throw Error("camera: fov, near and far must be finite numbers");
    if (!(c.nearZ > 0.0f)) throw Error("camera: near must be > 0");
    if (!(c.farZ > c.nearZ) || !std::isfinite(c.farZ)) throw Error("camera: far must be > near");
    // A 32-bit depth buffer spreads its precision as near/z: past ~1e8 every surface lands on the
    // same depth value and nothing renders (near 1e-9, far 1e9 gave an empty frame reported as
    // "fully occluded"). 2CylinderEngine's own camera (0.05 .. 1e6, 2e7) still passes.
    if (double(c.farZ) / double(c.nearZ) > kMaxFarNearRatio) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "camera: far/near = %.3g exceeds %.0e: the depth buffer cannot resolve it "
                      "(raise near, or fit the planes to the scene)", double(c.farZ) / double(c.nearZ), kMaxFarNearRatio);
        throw Error(buf);
    }
}

Camera parseCamera(const std::string& text, const Camera& base) {
    std::vector<float> v;
    std::stringstream ss(text);
    std::string tok;
    while (std::getline(ss, tok, ',')) {
        double d = 0;
        if (!parseDecimal(tok, d)) throw Error("--camera: '" + tok + "' is not a number");
        if (!std::isfinite(float(d))) throw Error("--camera: '" + tok + "' is not a finite number");
        v.push_back(float(d));
    }
    if (!(v.size() == 6 || v.size() == 9 || v.size() == 10 || v.size() == 12))
        throw Error(
            "--camera: expected 6, 9, 10 or 12 numbers (eye, target[, up[, fov[, near, far]]]), got " +
            std::to_string(v.size()));
    Camera c = base;
    c.eye = {v[0], v[1], v[2]};
    c.target = {v[3], v[4], v[5]};
    if (v.size() >= 9) c.up = {v[6], v[7], v[8]};
    if (v.size() >= 10) c.fovYDeg = v[9];
    if (v.size() >= 12) { // explicit planes are used as given
        c.nearZ = v[10];
        c.farZ = v[11];
        c.clip = ClipMode::Fixed;
    }
    validateCamera(c);
    return c;
}

} // namespace ssao
