#include "scene/camera_path.h"

#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace ssao {

void validateCameraPath(const CameraPathSpec& s) {
    if (s.frames < 2 || s.frames > 64)
        throw Error("motion path: " + std::to_string(s.frames) + " frames, expected 2..64");
    if (!std::isfinite(s.orbitDeg) || std::abs(s.orbitDeg) > 90.0f)
        throw Error("motion path: orbit " + std::to_string(s.orbitDeg) + " degrees, expected -90..90");
    if (!std::isfinite(s.dolly) || s.dolly < -0.5f || s.dolly > 0.9f)
        throw Error("motion path: dolly " + std::to_string(s.dolly) + ", expected -0.5..0.9 of the distance");
}

std::vector<Camera> cameraPath(const Camera& start, const CameraPathSpec& spec) {
    validateCameraPath(spec);
    validateCamera(start);
    std::vector<Camera> out;
    const glm::vec3 axis = glm::normalize(start.up);
    const glm::vec3 offset = start.eye - start.target;
    for (int k = 0; k < spec.frames; ++k) {
        const float t = float(k) / float(spec.frames - 1);
        const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(spec.orbitDeg * t), axis);
        Camera c = start;
        if (k > 0 && (spec.orbitDeg != 0.0f || spec.dolly != 0.0f)) // a still path keeps the start's eye bit for bit
            c.eye = start.target + glm::vec3(turn * glm::vec4(offset, 0.0f)) * (1.0f - spec.dolly * t);
        out.push_back(c);
    }
    return out;
}

} // namespace ssao
