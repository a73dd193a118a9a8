// Camera (right-handed, looks down -z in view space): a pinhole or an orthographic view, with a
// standard or a reversed-Z depth mapping.
#pragma once
#include <glm/glm.hpp>

#include <string>

namespace ssao {

struct Bounds;

// Fit: near/far are fitted to the scene's bounds for the current view every frame (tight planes:
// no z-fighting from a file's near 0.05 / far 1e6); Fixed: nearZ/farZ are used as they are.
enum class ClipMode { Fit, Fixed };

// Orthographic: parallel rays; the view spans the height a perspective camera with the same fov
// sees at the target's distance, so switching keeps the framing.
enum class Projection { Perspective, Orthographic };

// Standard: OpenGL's z_ndc in [-1, 1], depth 0 at near and 1 at far (a 32-bit float buffer still
// crowds its precision near 1). Reversed: glClipControl(GL_ZERO_TO_ONE), depth 1 at near and 0 at
// far, so the float's exponent spends its precision where 1/z does (Reed 2015, "Depth precision
// visualized"; Lapidous & Jiao 1999): z-fighting at far/near of 1e7 goes away, the far plane may be
// at infinity (farZ = +inf, perspective only).
enum class DepthMode { Standard, Reversed };

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDeg = 60.0f; // vertical field of view, degrees
    float nearZ = 0.1f;    // scene units, > 0
    float farZ = 100.0f;   // scene units, > near
    ClipMode clip = ClipMode::Fit;
    Projection projectionKind = Projection::Perspective;
    DepthMode depth = DepthMode::Reversed; // the robust choice: identical where standard works, clean where it z-fights

    glm::mat4 view() const;
    // View -> clip for this projection and depth mode (reversed: z_ndc in [0, 1], 1 at near).
    glm::mat4 projection(float aspect) const;
    // Orthographic: half the view's height in scene units (|target - eye| tan(fov / 2)).
    float orthoHalfHeight() const;
    bool orthographic() const { return projectionKind == Projection::Orthographic; }
    // Same view: every field the rendered image depends on.
    bool operator==(const Camera& o) const {
        return eye == o.eye && target == o.target && up == o.up && fovYDeg == o.fovYDeg && nearZ == o.nearZ &&
               farZ == o.farZ && clip == o.clip && projectionKind == o.projectionKind && depth == o.depth;
    }
    bool operator!=(const Camera& o) const { return !(*this == o); }
};

const char* projectionName(Projection p); // "perspective" | "orthographic"
const char* depthModeName(DepthMode d);   // "standard" | "reversed"
// Throws ssao::Error listing the accepted names.
Projection parseProjection(const std::string& name);
DepthMode parseDepthMode(const std::string& name);

// A camera that frames the bounds (looking from the front-right-above at the centre).
Camera frameBounds(const Bounds& b);

// Parses "ex,ey,ez,tx,ty,tz[,ux,uy,uz[,fov[,near,far]]]" (far may be "inf" with reversed depth).
// Throws ssao::Error naming the problem.
// The numbers are file coordinates; eye and target come back relative to `origin` (Scene::origin),
// subtracted in double.
Camera parseCamera(const std::string& text, const Camera& base, const glm::dvec3& origin = glm::dvec3(0.0));

// Throws when the camera would produce NaN matrices (zero direction, near <= 0, far <= near...)
// or a depth range the depth buffer cannot resolve (standard depth: far/near above
// kMaxFarNearRatio; reversed depth resolves any ratio a float holds, and an infinite far plane,
// down to a near plane of kMinReversedNear: near/z stays a normal float 1e8 x near away).
constexpr double kMaxFarNearRatio = 1e8;
constexpr float kMinReversedNear = 1e-30f;
void validateCamera(const Camera& c);

} // namespace ssao
