#include "metrics/reprojection.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ssao {

namespace {

// The camera's frame and lens in double, as the reference's primary rays build them.
struct Lens {
    glm::dvec3 eye, fwd, right, up;
    double tanHalf, aspect, orthoHalf;
    bool ortho;
    Lens(const Camera& c, int w, int h)
        : eye(c.eye), fwd(glm::normalize(glm::dvec3(c.target) - eye)),
          right(glm::normalize(glm::cross(fwd, glm::dvec3(c.up)))), up(glm::cross(right, fwd)),
          tanHalf(std::tan(glm::radians(double(c.fovYDeg)) * 0.5)), aspect(double(w) / double(h)),
          orthoHalf(glm::length(glm::dvec3(c.target) - eye) * tanHalf), ortho(c.orthographic()) {}
    // The point at view depth z on the ray through NDC (nx, ny).
    glm::dvec3 point(double nx, double ny, double z) const {
        if (ortho) return eye + right * (nx * orthoHalf * aspect) + up * (ny * orthoHalf) + fwd * z;
        return eye + (fwd + right * (nx * tanHalf * aspect) + up * (ny * tanHalf)) * z;
    }
    // NDC and view depth of a world point; false behind the eye (perspective).
    bool project(const glm::dvec3& p, double& nx, double& ny, double& z) const {
        const glm::dvec3 v = p - eye;
        z = glm::dot(v, fwd);
        if (ortho) {
            nx = glm::dot(v, right) / (orthoHalf * aspect), ny = glm::dot(v, up) / orthoHalf;
            return true;
        }
        if (!(z > 0.0)) return false;
        nx = glm::dot(v, right) / (z * tanHalf * aspect), ny = glm::dot(v, up) / (z * tanHalf);
        return true;
    }
};

bool reproject(const Lens& from, const Lens& to, int w, int h, int x, int y, float depth, float& tx, float& ty,
               float& tz) {
    const double nx = 2.0 * (x + 0.5) / w - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / h;
    double px = 0, py = 0, pz = 0;
    if (!to.project(from.point(nx, ny, double(depth)), px, py, pz)) return false;
    tx = float((px + 1.0) * 0.5 * w), ty = float((1.0 - py) * 0.5 * h), tz = float(pz);
    return std::isfinite(tx) && std::isfinite(ty);
}

} // namespace

bool reprojectPoint(const Camera& from, const Camera& to, int width, int height, int x, int y, float depth,
                    float& toX, float& toY, float& toDepth) {
    return reproject(Lens(from, width, height), Lens(to, width, height), width, height, x, y, depth, toX, toY,
                     toDepth);
}

std::vector<int> reprojectToPrevious(const DepthFrame& cur, const DepthFrame& prev, int w, int h, float tol) {
    if (w < 0 || h < 0) throw std::invalid_argument("reprojectToPrevious: negative size");
    if (!cur.camera || !prev.camera || !cur.depth || !prev.depth)
        throw std::invalid_argument("reprojectToPrevious: a camera or a depth image is missing");
    std::vector<int> out(size_t(w) * size_t(h), kDisoccluded);
    if (w == 0 || h == 0) return out;
    const Lens from(*cur.camera, w, h), to(*prev.camera, w, h);
    auto geometry = [](const DepthFrame& f, size_t i) { return (!f.geometry || f.geometry[i] > 0.0f) && f.depth[i] > 0.0f; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            float tx = 0, ty = 0, tz = 0;
            if (!geometry(cur, i)) continue;
            if (!reproject(from, to, w, h, x, y, cur.depth[i], tx, ty, tz) || tx < 0.0f || ty < 0.0f || tx > float(w) ||
                ty > float(h)) {
                out[i] = kOffScreen;
                continue;
            }
            // The 2x2 pixel centres around the point: the nearest whose depth agrees, or, on a
            // surface that slopes away faster than the tolerance per pixel, the nearest when the
            // four interpolate to the point's depth (1/z is affine in screen space on a plane).
            const int x0 = int(std::floor(tx - 0.5f)), y0 = int(std::floor(ty - 0.5f));
            double best = 1e30, nearest = 1e30, inv = 0;
            int four = 0, nearestIndex = kDisoccluded;
            for (int dy = 0; dy <= 1; ++dy)
                for (int dx = 0; dx <= 1; ++dx) {
                    const int qx = std::clamp(x0 + dx, 0, w - 1), qy = std::clamp(y0 + dy, 0, h - 1);
                    const size_t j = size_t(qy) * w + qx;
                    if (!geometry(prev, j)) continue;
                    const double d = std::hypot(qx + 0.5 - tx, qy + 0.5 - ty);
                    const double wx = dx ? tx - 0.5 - x0 : 1.0 - (tx - 0.5 - x0), wy = dy ? ty - 0.5 - y0 : 1.0 - (ty - 0.5 - y0);
                    inv += wx * wy * (to.ortho ? prev.depth[j] : 1.0 / prev.depth[j]), ++four;
                    if (d < nearest) nearest = d, nearestIndex = int(j);
                    if (std::abs(prev.depth[j] - tz) <= tol * tz && d < best) best = d, out[i] = int(j);
                }
            const double z = to.ortho ? inv : 1.0 / inv;
            if (out[i] < 0 && four == 4 && std::abs(z - tz) <= tol * tz) out[i] = nearestIndex;
        }
    return out;
}

} // namespace ssao
