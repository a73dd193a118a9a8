// A camera path through a view for the motion score (metrics/motion_metrics.h): an orbit of a few
// degrees about the view's target and, at the same time, a dolly toward it - what a user does
// who looks around a model. Deterministic: the same view and spec give the same cameras.
#pragma once
#include "scene/camera.h"

#include <vector>

namespace ssao {

struct CameraPathSpec {
    int frames = 8;       // cameras on the path, the start included (2..64)
    float orbitDeg = 4.0f; // total orbit about the target, about the camera's up axis, degrees
    float dolly = 0.1f;   // total move toward the target, as a fraction of the start's distance
    unsigned maxMib = 2048; // what a run may keep of the path's frames at once (--motion-max-mib; app/measure/motion_measure.h)
};

// Throws ssao::Error naming the field when a spec is outside its range (frames 2..64, orbit
// -90..90 degrees, dolly -0.5..0.9).
void validateCameraPath(const CameraPathSpec& spec);

// `spec.frames` cameras: the first is `start`, camera k is turned by orbitDeg * k / (frames - 1)
// about the target and moved toward it by dolly * k / (frames - 1) of the start's distance (even
// steps). Lens, up, clip planes and depth mode are the start's.
std::vector<Camera> cameraPath(const Camera& start, const CameraPathSpec& spec);

} // namespace ssao
