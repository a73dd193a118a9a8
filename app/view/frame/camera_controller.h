// Orbit (default) and fly navigation, as pure math on a Camera: testable without a window.
#pragma once
#include "scene/camera.h"

namespace ssao {

class CameraController {
  public:
    enum class Mode { Orbit, Fly };

    // Adopts `c` (e.g. the scene's camera or a bookmark); the scene's size scales speeds. Fitted
    // clip planes are the renderer's business; a camera with its own (Fixed) planes gets them
    // widened as it moves, so orbiting or zooming out never clips the scene it was made for.
    void reset(const Camera& c, float sceneRadius, glm::vec3 sceneCenter);
    void reset(const Camera& c, float sceneRadius) { reset(c, sceneRadius, c.target); }
    void setClip(ClipMode m) { cam_.clip = m; }
    void setProjection(Projection p) { cam_.projectionKind = p; }
    void setDepth(DepthMode d) { cam_.depth = d; }
    void setMode(Mode m) { mode_ = m; }
    Mode mode() const { return mode_; }

    // Mouse drag in pixels of a view `viewWidth` wide: a drag across the whole width turns half a
    // turn (pi), whatever the window's size (a fixed 0.005 rad/px turned a small window too fast).
    // Orbit: rotate around the target; fly: look around.
    void rotate(float dxPixels, float dyPixels, float viewWidth = kDefaultViewWidth);
    static constexpr float kDefaultViewWidth = 628.3185f; // pi / 0.005: 0.005 rad per pixel
    // Pan the view (target and eye together), in pixels of a viewport `viewportHeight` tall.
    void pan(float dxPixels, float dyPixels, float viewportHeight);
    // Scroll: dolly towards the target (orbit) or move forward (fly).
    void zoom(float steps);
    // Fly: move along (right, up, forward) by `amount` scene radii.
    void move(const glm::vec3& rightUpForward, float amount);

    const Camera& camera() const { return cam_; }

  private:
    void widenFixedClip();
    Camera cam_;
    glm::vec3 center_{0.0f};
    float radius_ = 1.0f;
    Mode mode_ = Mode::Orbit;
};

} // namespace ssao
