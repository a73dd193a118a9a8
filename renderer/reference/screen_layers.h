// The screen-space oracle's view of a frame: what a G-buffer holds, and nothing else. Per pixel
// and per depth layer, the surface the pixel centre's ray met (its point and geometric normal:
// its tangent plane); a surface is solid for `thickness` behind itself along the view ray (an
// infinite thickness is the height-field assumption GTAO makes). A ray is occluded when a point
// of it within R lies behind a layer's surface, within that thickness, at a pixel other than its
// own; a point off screen or behind the camera is unknown to the screen, so it occludes nothing.
// A second layer that is a back face (the far side of the first layer's solid, as a back-face
// depth buffer holds it) bounds that solid instead: the first surface is solid exactly down to it,
// and the back face occludes nothing behind itself. A second layer that faces the camera is
// another surface, solid for `thickness` behind itself like the first. A cut-out surface (a MASK
// material: foliage, fences, labels on quads) is a sheet with no thickness: it blocks a ray only
// where the ray crosses it, from either side (a G-buffer can mark such pixels by their material).
// The ground truth (reference_ao.h) asks the scene instead; the difference between the two is
// what no screen-space technique with these buffers can see.
#pragma once
#include "scene/camera.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ssao {

// What the oracle's G-buffer may take: 1 GiB (a 4K frame with a 256-pixel band and two layers
// takes 0.6 GiB; a 64 x 36 frame with a 4096-pixel band and two layers would take 3.5 GiB).
constexpr uint64_t kScreenLayersBudget = uint64_t(1) << 30;

// What a layer's surface is: the front of a solid (solid for the thickness behind it), the far side
// of the first layer's solid (layer 1 only), or a sheet (no thickness).
enum class SurfaceKind { Solid, BackFace, Sheet };

class ScreenLayers {
  public:
    // `thickness` in scene units (may be +inf); `layers` 1 (a G-buffer) or 2 (a deep G-buffer);
    // `guard` pixels of margin held beyond each edge of the width x height frame (a guard band).
    // Checks the budget (checkBudget) before anything is allocated.
    ScreenLayers(const Camera& camera, int width, int height, int layers, float thickness, int guard = 0);

    // Bytes the G-buffer of these dimensions takes: every layer's (width + 2 guard) x (height + 2
    // guard) surfaces. Pure: callers check it before a render (app/commands/render/render_command.cpp).
    static uint64_t bytes(int width, int height, int layers, int guard);
    // Throws "screen oracle: its G-buffer would take X GiB (...), past the budget of 1 GiB: lower
    // --oracle-guard or --oracle-layers" when bytes() exceeds kScreenLayersBudget.
    static void checkBudget(int width, int height, int layers, int guard);

    // The surface of `layer` at `pixel` of the frame (row-major, top row first), or at (x, y) with
    // x in [-guard, width + guard) and y likewise.
    // BackFace: the surface faces away from the camera (layer 1 only: the first layer's far side).
    void set(int layer, size_t pixel, const glm::vec3& point, const glm::vec3& normal,
             SurfaceKind kind = SurfaceKind::Solid);
    void set(int layer, int x, int y, const glm::vec3& point, const glm::vec3& normal,
             SurfaceKind kind = SurfaceKind::Solid);
    int guard() const { return guard_; }

    // Marches o + t d for t in (0, R] one pixel at a time.
    bool occluded(const glm::vec3& o, const glm::vec3& d, float R, size_t ownPixel) const;

    // The pixel (frame coordinates, the guard band included) whose area holds world point `p`
    // (false when outside the held area or behind the eye).
    bool project(const glm::vec3& p, int& x, int& y, float& fx, float& fy) const;

  private:
    bool toScreen(const glm::vec3& p, float& fx, float& fy) const;
    struct Surface {
        glm::vec3 p{0.0f}, n{0.0f};
        bool valid = false;
        bool back = false;
        bool sheet = false;
    };
    // Whether the step from `before` to `q` is blocked by s, a surface that is not a back face.
    bool blocks(const Surface& s, const glm::vec3& q, const glm::vec3& before) const;
    // How far q lies behind the surface's tangent plane along the view ray through q (negative: in
    // front); NaN for no surface.
    float gapBehind(const Surface& s, const glm::vec3& q) const;

    glm::vec3 eye_, fwd_, right_, up_;
    float tanHalf_, aspect_, orthoHalf_, near_;
    bool ortho_;
    size_t index(int x, int y) const { return size_t(y + guard_) * size_t(width_ + 2 * guard_) + size_t(x + guard_); }
    int width_, height_, layers_, guard_;
    float thickness_;
    std::vector<Surface> surfaces_; // layer-major
};

} // namespace ssao
