#include "reference/screen_layers.h"

#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ssao {

ScreenLayers::ScreenLayers(const Camera& c, int width, int height, int layers, float thickness, int guard)
    : eye_(c.eye), fwd_(glm::normalize(c.target - c.eye)), right_(glm::normalize(glm::cross(fwd_, c.up))),
      up_(glm::cross(right_, fwd_)), tanHalf_(std::tan(glm::radians(c.fovYDeg) * 0.5f)),
      aspect_(float(width) / float(height)), orthoHalf_(glm::length(c.target - c.eye) * tanHalf_),
      near_(c.nearZ), ortho_(c.orthographic()), width_(width), height_(height), layers_(layers), guard_(guard),
      thickness_(thickness) {
    if (layers < 1 || layers > 2) throw Error("screen oracle: 1 or 2 depth layers");
    if (!(thickness > 0.0f)) throw Error("screen oracle: the thickness must be positive");
    if (guard < 0 || guard > 4096) throw Error("screen oracle: a guard band of 0..4096 pixels");
    checkBudget(width, height, layers, guard);
    surfaces_.assign(size_t(width + 2 * guard) * size_t(height + 2 * guard) * layers, Surface{});
}

uint64_t ScreenLayers::bytes(int width, int height, int layers, int guard) {
    const uint64_t w = uint64_t(std::max(width, 0)) + 2 * uint64_t(std::max(guard, 0));
    const uint64_t h = uint64_t(std::max(height, 0)) + 2 * uint64_t(std::max(guard, 0));
    return w * h * uint64_t(std::max(layers, 0)) * sizeof(Surface);
}

void ScreenLayers::checkBudget(int width, int height, int layers, int guard) {
    const uint64_t need = bytes(width, height, layers, guard);
    if (need <= kScreenLayersBudget) return;
    char text[320];
    std::snprintf(text, sizeof text,
                  "screen oracle: its G-buffer would take %.2f GiB ((%d + 2 x %d) x (%d + 2 x %d) pixels x %d layer%s x "
                  "%zu bytes), past the budget of %.3g GiB: lower --oracle-guard (pixels beyond each edge) or "
                  "--oracle-layers, or render smaller",
                  double(need) / double(1 << 30), width, guard, height, guard, layers, layers == 1 ? "" : "s",
                  sizeof(Surface), double(kScreenLayersBudget) / double(1 << 30));
    throw Error(text);
}

void ScreenLayers::set(int layer, size_t pixel, const glm::vec3& point, const glm::vec3& normal, SurfaceKind kind) {
    set(layer, int(pixel % size_t(width_)), int(pixel / size_t(width_)), point, normal, kind);
}

void ScreenLayers::set(int layer, int x, int y, const glm::vec3& point, const glm::vec3& normal, SurfaceKind kind) {
    const size_t plane = size_t(width_ + 2 * guard_) * size_t(height_ + 2 * guard_);
    surfaces_[size_t(layer) * plane + index(x, y)] = {point, normal, true, kind == SurfaceKind::BackFace && layer == 1,
                                                      kind == SurfaceKind::Sheet};
}

// The rasteriser's mapping (reference_ao.cpp PrimaryRays): NDC x = 2 (x + 0.5) / W - 1, y up;
// window coordinates, unbounded. False behind the near plane.
bool ScreenLayers::toScreen(const glm::vec3& p, float& fx, float& fy) const {
    const glm::vec3 v = p - eye_;
    const float z = glm::dot(v, fwd_);
    if (!(z > near_)) return false;
    const float sx = glm::dot(v, right_), sy = glm::dot(v, up_);
    const float nx = ortho_ ? sx / (orthoHalf_ * aspect_) : sx / (z * tanHalf_ * aspect_);
    const float ny = ortho_ ? sy / orthoHalf_ : sy / (z * tanHalf_);
    fx = (nx + 1.0f) * 0.5f * float(width_);
    fy = (1.0f - ny) * 0.5f * float(height_);
    return true;
}

bool ScreenLayers::project(const glm::vec3& p, int& x, int& y, float& fx, float& fy) const {
    const float g = float(guard_);
    if (!toScreen(p, fx, fy) || !(fx >= -g && fx < float(width_) + g && fy >= -g && fy < float(height_) + g))
        return false;
    x = int(std::floor(fx)), y = int(std::floor(fy));
    return true;
}

// u - s = dot(P - q, N) / dot(r, N): the plane's distance along r minus q's.
float ScreenLayers::gapBehind(const Surface& s, const glm::vec3& q) const {
    if (!s.valid) return std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 r = ortho_ ? fwd_ : glm::normalize(q - eye_);
    const float rn = glm::dot(r, s.n);
    if (std::abs(rn) > 1e-3f) return -glm::dot(s.p - q, s.n) / rn;
    return glm::dot(q - eye_, r) - glm::dot(s.p - eye_, r); // edge-on: the two points' distances along r
}

bool ScreenLayers::blocks(const Surface& s, const glm::vec3& q, const glm::vec3& before) const {
    const float g = gapBehind(s, q);
    if (s.sheet) return (g > 0.0f) != (gapBehind(s, before) > 0.0f); // the step crossed its plane here
    return g > 0.0f && g <= thickness_;
}

bool ScreenLayers::occluded(const glm::vec3& o, const glm::vec3& d, float R, size_t ownPixel) const {
    // The part in front of the near plane (behind it the screen holds nothing).
    float tEnd = R;
    const float zo = glm::dot(o - eye_, fwd_), dz = glm::dot(d, fwd_);
    if (zo + dz * R <= near_) {
        if (dz >= 0.0f) return false;
        tEnd = (near_ * 1.0001f - zo) / dz;
        if (!(tEnd > 0.0f)) return false;
    }
    // Steps of at most one pixel between the projected ends (at least one, at most 512).
    float ax, ay, bx, by;
    if (!toScreen(o, ax, ay) || !toScreen(o + d * tEnd, bx, by)) return false;
    const float pixels = std::max(std::abs(bx - ax), std::abs(by - ay));
    const int steps = std::clamp(int(std::ceil(pixels)), 1, 512);
    const size_t plane = size_t(width_ + 2 * guard_) * size_t(height_ + 2 * guard_);
    const size_t own = index(int(ownPixel % size_t(width_)), int(ownPixel / size_t(width_)));
    glm::vec3 prev = o;
    for (int k = 1; k <= steps; ++k) {
        const glm::vec3 q = o + d * (tEnd * float(k) / float(steps));
        const glm::vec3 before = prev;
        prev = q;
        int x, y;
        float fx, fy;
        if (!project(q, x, y, fx, fy)) continue; // not on the screen: unknown, occludes nothing
        const size_t px = index(x, y);
        if (px == own) continue;
        if (surfaces_[px].sheet) {
            if (blocks(surfaces_[px], q, before)) return true;
            // A back face behind a sheet: its solid's front is hidden, and it occludes nothing behind itself.
            if (layers_ > 1 && !surfaces_[plane + px].back && blocks(surfaces_[plane + px], q, before)) return true;
            continue;
        }
        const float g0 = gapBehind(surfaces_[px], q);
        if (layers_ > 1 && surfaces_[plane + px].back) {
            // The first surface's solid ends at its back face: between the two, whatever the
            // thickness; a step that crossed the front plane and lands beyond the back face passed
            // through the solid (a shell thinner than a step is not stepped over).
            const Surface& back = surfaces_[plane + px];
            const float g1 = gapBehind(back, q);
            if (g0 > 0.0f && (!(g1 > 0.0f) || !(gapBehind(surfaces_[px], before) > 0.0f))) return true;
            // (The mirror case, a step from beyond the back face to in front of the front plane, is
            // not tested: with the planes extended past their pixels it fires on rays leaving
            // neighbouring surfaces and over-occludes.)
            continue;
        }
        if (g0 > 0.0f && g0 <= thickness_) return true;
        if (layers_ > 1 && blocks(surfaces_[plane + px], q, before)) return true;
    }
    return false;
}

} // namespace ssao
