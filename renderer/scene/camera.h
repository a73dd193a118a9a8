// Pinhole camera (right-handed, looks down -z in view space, OpenGL clip conventions).
#pragma once
#include <glm/glm.hpp>

#include <string>

namespace ssao {

struct Bounds;

// Fit: near/far are fitted to the scene's bounds for the current view every frame (tight planes:
// no z-fighting from a file's near 0.05 / far 1e6); Fixed: nearZ/farZ are used as they are.
enum class ClipMode { Fit, Fixed };

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDeg = 60.0f; // vertical field of view, degrees
    float nearZ = 0.1f;    // scene units, > 0
    float farZ = 100.0f;   // scene units, > near
    ClipMode clip = ClipMode::Fit;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
};

// A camera that frames the bounds (looking from the front-right-above at the centre).
Camera frameBounds(const Bounds& b);

// Parses "ex,ey,ez,tx,ty,tz[,ux,uy,uz[,fov[,near,far]]]". Throws ssao::Error naming the problem.
Camera parseCamera(const std::string& text, const Camera& base);

// Throws when the camera would produce NaN matrices (zero direction, near <= 0, far <= near...)
// or a depth range the depth buffer cannot resolve (far/near above kMaxFarNearRatio).
constexpr double kMaxFarNearRatio = 1e8;
void validateCamera(const Camera& c);

} // namespace ssao
