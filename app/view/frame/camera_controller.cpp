#include "view/frame/camera_controller.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ssao {

namespace {
constexpr float kMaxPitch = 1.55f; // just short of straight up/down, where lookAt degenerates
} // namespace

void CameraController::reset(const Camera& c, float sceneRadius, glm::vec3 sceneCenter) {
    cam_ = c;
    radius_ = std::max(sceneRadius, 1e-6f);
    center_ = sceneCenter;
    // Orbiting keeps world +y (or the camera's up) as the axis; normalise up to avoid drift.
    cam_.up = glm::normalize(cam_.up);
}

void CameraController::rotate(float dx, float dy, float viewWidth) {
    const float kRadiansPerPixel = 3.14159265f / std::max(viewWidth, 1.0f);
    glm::vec3 offset = cam_.eye - cam_.target; // orbit: eye around target; fly: target around eye
    if (mode_ == Mode::Fly) offset = -offset;
    const float dist = glm::length(offset);
    glm::vec3 dir = offset / dist;
    float yaw = std::atan2(dir.x, dir.z);
    float pitch = std::asin(std::clamp(dir.y, -1.0f, 1.0f));
    const float sign = mode_ == Mode::Fly ? 1.0f : -1.0f;
    yaw += sign * dx * kRadiansPerPixel;
    pitch = std::clamp(pitch + (mode_ == Mode::Fly ? -dy : dy) * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
    dir = glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    if (mode_ == Mode::Orbit)
        cam_.eye = cam_.target + dir * dist;
    else
        cam_.target = cam_.eye + dir * dist;
    cam_.up = {0.0f, 1.0f, 0.0f};
    widenFixedClip();
}

void CameraController::pan(float dx, float dy, float viewportHeight) {
    const glm::vec3 fwd = glm::normalize(cam_.target - cam_.eye);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, cam_.up));
    const glm::vec3 up = glm::cross(right, fwd);
    // One pixel moves the point under the cursor by one pixel at the target's distance.
    const float dist = glm::length(cam_.target - cam_.eye);
    const float perPixel =
        2.0f * dist * std::tan(glm::radians(cam_.fovYDeg) * 0.5f) / std::max(viewportHeight, 1.0f);
    const glm::vec3 d = (-dx * right + dy * up) * perPixel;
    cam_.eye += d;
    cam_.target += d;
    widenFixedClip();
}

void CameraController::zoom(float steps) {
    const glm::vec3 offset = cam_.eye - cam_.target;
    if (mode_ == Mode::Orbit) {
        const float dist =
            std::clamp(glm::length(offset) * std::pow(0.9f, steps), radius_ * 1e-3f, radius_ * 100.0f);
        cam_.eye = cam_.target + glm::normalize(offset) * dist;
        widenFixedClip();
    } else {
        move({0.0f, 0.0f, 1.0f}, 0.1f * steps);
    }
}

void CameraController::move(const glm::vec3& ruf, float amount) {
    const glm::vec3 fwd = glm::normalize(cam_.target - cam_.eye);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, cam_.up));
    const glm::vec3 up = glm::cross(right, fwd);
    const glm::vec3 d = (ruf.x * right + ruf.y * up + ruf.z * fwd) * amount * radius_;
    cam_.eye += d;
    cam_.target += d;
    widenFixedClip();
}

void CameraController::widenFixedClip() {
    if (cam_.clip != ClipMode::Fixed) return;
    // Far stays beyond the whole scene, near in front of the target (ratio kept under 1e5: float
    // depth keeps ~1e-6 relative precision there).
    const float toCenter = glm::length(center_ - cam_.eye), toTarget = glm::length(cam_.target - cam_.eye);
    cam_.farZ = std::max(cam_.farZ, toCenter + 1.5f * radius_);
    cam_.nearZ = std::min(cam_.nearZ, 0.5f * toTarget);
    cam_.nearZ = std::max(cam_.nearZ, cam_.farZ * 1e-5f);
}

} // namespace ssao
