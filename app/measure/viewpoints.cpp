#include "measure/viewpoints.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace ssao {

std::vector<std::pair<std::string, Camera>> viewpoints(const Camera& base, int count) {
    std::vector<std::pair<std::string, Camera>> out{{"camera", base}};
    const glm::vec3 up = glm::normalize(base.up);
    for (int k = 1; k < count; ++k) {
        const int step = (k + 1) / 2;              // 1, 1, 2, 2, 3, ...
        const float sign = (k % 2) ? 1.0f : -1.0f; // +, -, +, -
        const float azimuth = sign * 25.0f * float(step);
        Camera c = base;
        glm::vec3 offset = base.eye - base.target;
        offset = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(azimuth), up) * glm::vec4(offset, 0.0f));
        // Elevation: ±8° per step about the horizontal axis, kept away from the poles.
        const glm::vec3 side = glm::cross(up, offset);
        if (glm::length(side) > 1e-6f * glm::length(offset)) {
            const float elevation = (step % 2 ? 8.0f : -8.0f);
            const glm::vec3 rotated =
                glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(elevation), glm::normalize(side)) *
                          glm::vec4(offset, 0.0f));
            if (std::abs(glm::dot(glm::normalize(rotated), up)) < 0.97f) offset = rotated;
        }
        c.eye = base.target + offset;
        char name[32];
        std::snprintf(name, sizeof name, "orbit%+d", int(azimuth));
        out.emplace_back(name, c);
    }
    return out;
}

} // namespace ssao
