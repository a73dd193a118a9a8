#include "reference/reference_ao.h"

#include "reference/ray_offset.h"
#include "reference/sampling.h"
#include "util/error.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <thread>

namespace ssao {

const char* variantName(ReferenceVariant v) {
    return v == ReferenceVariant::Obscurance ? "obscurance" : "visibility";
}

ReferenceVariant parseVariant(const std::string& name) {
    if (name == "visibility") return ReferenceVariant::Visibility;
    if (name == "obscurance") return ReferenceVariant::Obscurance;
    throw Error("reference variant '" + name + "' is not one of: visibility, obscurance");
}

namespace {

// Runs fn(row) for every row on `threads` threads (rows handed out one at a time, so uneven rows
// balance); calls progress(fraction) from the calling thread while they work.
template <class Fn>
void parallelRows(int rows, int threads, Fn fn, const ReferenceTracer::Progress& progress) {
    std::atomic<int> next{0}, finished{0};
    std::mutex m;
    std::condition_variable cv;
    int running = threads;
    auto worker = [&] {
        for (int y; (y = next.fetch_add(1)) < rows;) {
            fn(y);
            finished.fetch_add(1);
        }
        std::lock_guard<std::mutex> lock(m);
        if (--running == 0) cv.notify_all();
    };
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i)
        pool.emplace_back(worker);
    {
        std::unique_lock<std::mutex> lock(m);
        while (running > 0) {
            cv.wait_for(lock, std::chrono::milliseconds(200));
            if (progress) progress(double(finished.load()) / std::max(rows, 1));
        }
    }
    for (auto& t : pool)
        t.join();
}

int threadCount(int requested) {
    if (requested > 0) return requested;
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": no singularity anywhere.
void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float s = std::copysign(1.0f, n.z);
    const float a = -1.0f / (s + n.z);
    const float c = n.x * n.y * a;
    t = {1.0f + s * n.x * n.x * a, s * c, -s * n.x};
    b = {c, s + n.y * n.y * a, -n.y};
}

uint32_t pixelSeed(int x, int y) {
    return sampling::hash32(sampling::hashCombine(sampling::hash32(uint32_t(x)), uint32_t(y)));
}

constexpr int kBatch = 256; // rays handed to Embree per stream call

// The rasteriser's camera (glm::lookAt + Camera::projection): pixel centre (x + 0.5, y + 0.5),
// y from the top, maps to NDC (2(x+0.5)/W - 1, 1 - 2(y+0.5)/H).
struct PrimaryRays {
    glm::dvec3 eye, fwd, right, up;
    double tanHalf, aspect, orthoHalf;
    bool ortho;
    int width, height;
    PrimaryRays(const Camera& c, int w, int h)
        : eye(c.eye), fwd(glm::normalize(glm::dvec3(c.target) - eye)),
          right(glm::normalize(glm::cross(fwd, glm::dvec3(c.up)))), up(glm::cross(right, fwd)),
          tanHalf(std::tan(glm::radians(double(c.fovYDeg)) * 0.5)), aspect(double(w) / double(h)),
          orthoHalf(glm::length(glm::dvec3(c.target) - eye) * tanHalf), ortho(c.orthographic()), width(w),
          height(h) {}
    // Orthographic: parallel rays from the eye plane, the view spanning +-orthoHalf.
    void ray(int x, int y, glm::dvec3& org, glm::dvec3& d) const {
        const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height;
        d = ortho ? fwd : glm::normalize(fwd + right * (nx * tanHalf * aspect) + up * (ny * tanHalf));
        org = ortho ? eye + right * (nx * orthoHalf * aspect) + up * (ny * orthoHalf) : eye;
    }
};

// One pixel's primary ray against the scene, limited to what lies between the clip planes (the
// rasteriser draws nothing else; view depth = t * cosFwd): the frame's pixels and the guard band's.
struct PrimaryHit {
    bool hit = false;
    alignas(16) RTCRayHit rh{};
    glm::dvec3 org{0.0}, d{0.0};
    double cosFwd = 1.0;
    float far = INFINITY; // the far plane along this ray
    glm::vec3 point() const { return glm::vec3(org + d * double(rh.ray.tfar)); }
};

PrimaryHit tracePrimary(RTCScene scene, RTCIntersectContext& ctx, const PrimaryRays& rays, const Camera& camera,
                        int x, int y) {
    PrimaryHit h;
    rays.ray(x, y, h.org, h.d);
    h.cosFwd = glm::dot(h.d, rays.fwd);
    h.far = std::isinf(camera.farZ) ? INFINITY : float(camera.farZ / h.cosFwd);
    RTCRayHit& rh = h.rh;
    rh.ray.org_x = float(h.org.x), rh.ray.org_y = float(h.org.y), rh.ray.org_z = float(h.org.z);
    rh.ray.dir_x = float(h.d.x), rh.ray.dir_y = float(h.d.y), rh.ray.dir_z = float(h.d.z);
    rh.ray.tnear = float(camera.nearZ / h.cosFwd);
    rh.ray.tfar = h.far;
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &ctx, &rh);
    h.hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    return h;
}

// Whether a surface lies within a few ULPs of `o` along either normal (coincident faces: the
// shortest way to a parallel twin): of the hit's own coordinates or of the primary distance,
// whichever is coarser - a camera far away orders two faces closer than its ULPs at random, and
// the offsets clear only the hit's.
bool coincidentFace(RTCScene scene, const glm::vec3& o, const glm::vec3& ng, const glm::vec3& n, float coarse) {
    for (const glm::vec3& dir : {ng, n}) {
        alignas(16) RTCRay probe{};
        probe.org_x = o.x, probe.org_y = o.y, probe.org_z = o.z;
        probe.dir_x = dir.x, probe.dir_y = dir.y, probe.dir_z = dir.z;
        probe.tnear = 0.0f;
        probe.tfar = coincidenceDistance(coarse);
        probe.mask = 0xffffffffu;
        RTCIntersectContext near;
        rtcInitIntersectContext(&near);
        rtcOccluded1(scene, &near, &probe);
        if (probe.tfar < 0.0f) return true; // Embree sets tfar = -inf on a hit
    }
    return false;
}

} // namespace

ReferenceTracer::ReferenceTracer(const EmbreeScene& scene, const Camera& camera, int width, int height,
                                 const ReferenceSettings& settings)
    : scene_(scene), width_(width), height_(height), settings_(settings) {
    if (width <= 0 || height <= 0) throw Error("reference: empty image size");
    if (!(settings.radius > 0.0f) || !std::isfinite(settings.radius))
        throw Error("reference: the radius must be a positive finite number of scene units");
    if (settings.samples < 1) throw Error("reference: at least one ray per pixel is needed");
    validateCamera(camera);
    if (settings.visibility == ReferenceVisibility::Screen && settings.variant != ReferenceVariant::Visibility)
        throw Error("screen oracle: only the visibility variant");
    if (settings.visibility == ReferenceVisibility::Screen)
        screen_ = std::make_unique<ScreenLayers>(camera, width, height, settings.layers,
                                                 settings.thickness * settings.radius, settings.guardBand);
    const size_t n = size_t(width) * size_t(height);
    hits_.assign(n, Hit{});
    depth_.assign(n, 0.0f);
    geometry_.assign(n, 0.0f);
    ambiguous_.assign(n, 0.0f);
    unoccluded_.assign(n, 0u);
    if (settings.variant == ReferenceVariant::Obscurance) {
        sumW_.assign(n, 0.0);
        sumW2_.assign(n, 0.0);
    }
    const PrimaryRays rays(camera, width, height);
    parallelRows(height, threadCount(settings.threads), [&](int y) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        for (int x = 0; x < width; ++x) {
            const PrimaryHit h = tracePrimary(scene.handle(), ctx, rays, camera, x, y);
            if (!h.hit) continue;
            const size_t i = size_t(y) * width + x;
            storeHit(i, h.rh, glm::vec3(h.d));
            depth_[i] = float(double(h.rh.ray.tfar) * h.cosFwd);
            geometry_[i] = 1.0f;
            if (screen_ && settings.layers > 1) storeSecondLayer(x, y, h.point(), glm::vec3(h.d), h.far);
        }
    }, {});
    if (screen_ && settings.guardBand > 0) traceGuardBand(camera);
}

void ReferenceTracer::traceGuardBand(const Camera& camera) {
    const int g = settings_.guardBand;
    const PrimaryRays rays(camera, width_, height_); // linear in x, y: pixels beyond the edges too
    parallelRows(height_ + 2 * g, threadCount(settings_.threads), [&](int row) {
        const int y = row - g;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (int x = -g; x < width_ + g; ++x) {
            if (x >= 0 && x < width_ && y >= 0 && y < height_) continue; // the frame: traced already
            const PrimaryHit h = tracePrimary(scene_.handle(), ctx, rays, camera, x, y);
            if (!h.hit) continue;
            const RTCRayHit& rh = h.rh;
            const glm::dvec3 d = h.d;
            glm::vec3 ng = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
            if (glm::dot(ng, glm::vec3(d)) > 0.0f) ng = -ng;
            const glm::vec3 p = h.point();
            screen_->set(0, x, y, p, ng, kindOf(rh.hit.primID));
            if (settings_.layers > 1) storeSecondLayer(x, y, p, glm::vec3(d), h.far);
        }
    }, {});
}

SurfaceKind ReferenceTracer::kindOf(unsigned primID) const {
    return scene_.sheet(primID) ? SurfaceKind::Sheet : SurfaceKind::Solid;
}

void ReferenceTracer::storeHit(size_t i, const RTCRayHit& rh, const glm::vec3& d) {
    const Scene& sc = scene_.scene();
    const uint32_t* tri = &sc.indices[size_t(rh.hit.primID) * 3];
    const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
    // Barycentric position: exact to the triangle's precision, unlike org + t * dir.
    const glm::vec3 p =
        w * sc.vertices[tri[0]].position + u * sc.vertices[tri[1]].position + v * sc.vertices[tri[2]].position;
    glm::vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const float ngLen = glm::length(ng);
    ng = ngLen > 0.0f ? ng / ngLen : -d;
    if (glm::dot(ng, d) > 0.0f) ng = -ng; // the face the camera sees
    glm::vec3 n = w * sc.vertices[tri[0]].normal + u * sc.vertices[tri[1]].normal + v * sc.vertices[tri[2]].normal;
    const float nLen = glm::length(n);
    n = nLen > 1e-10f ? n / nLen : ng;  // interpolated normals are shorter than 1
    if (glm::dot(n, ng) < 0.0f) n = -n; // as the G-buffer: shade the side we see
    float scale = 0.0f; // the largest |coordinate| of the triangle: its vertices' precision
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 a = glm::abs(sc.vertices[tri[k]].position);
        scale = std::max({scale, a.x, a.y, a.z});
    }
    const glm::vec3 o = offsetRayOrigin(backOffTowardEye(p, -d, scale), ng);
    hits_[i] = Hit{o.x, o.y, o.z, n.x, n.y, n.z};
    if (screen_) screen_->set(0, i, p, ng, kindOf(rh.hit.primID)); // the oracle's first layer: its tangent plane
    if (coincidentFace(scene_.handle(), o, ng, n, std::max(scale, rh.ray.tfar))) ambiguous_[i] = 1.0f;
}

// The second layer: the first layer's back face when the view ray meets one next (the solid's true
// thickness, as a back-face depth buffer holds it), else the nearest surface at least
// layerSeparation x R behind the first (a deep G-buffer's second layer, Mara et al. 2016).
void ReferenceTracer::storeSecondLayer(int x, int y, const glm::vec3& p, const glm::vec3& d, float far) {
    unsigned prim = 0;
    auto nearest = [&](float offset, glm::vec3& hit, glm::vec3& ng) {
        alignas(16) RTCRayHit rh{};
        const glm::vec3 o = p + d * offset;
        rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
        rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = far;
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(scene_.handle(), &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        ng = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
        hit = o + d * rh.ray.tfar;
        prim = rh.hit.primID;
        return true;
    };
    glm::vec3 hit, ng;
    // Just behind the first surface (256 ULPs of its coordinates, as the AO rays' own back-off).
    const float eps = 256.0f * std::numeric_limits<float>::epsilon() *
                      std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
    if (nearest(eps, hit, ng) && glm::dot(ng, d) > 0.0f && !scene_.sheet(prim)) { // a sheet bounds no solid
        screen_->set(1, x, y, hit, -ng, SurfaceKind::BackFace); // stored facing the viewer
        return;
    }
    if (!nearest(settings_.layerSeparation * settings_.radius, hit, ng)) return;
    if (glm::dot(ng, d) > 0.0f) ng = -ng; // as a G-buffer would store it: facing the viewer
    screen_->set(1, x, y, hit, ng, kindOf(prim));
}

// A stream of AO rays handed to Embree kBatch at a time; each result lands in its pixel's tallies.
class ReferenceTracer::RayBatch {
  public:
    RayBatch(ReferenceTracer& t) : t_(t), obscurance_(t.settings_.variant == ReferenceVariant::Obscurance) {
        rtcInitIntersectContext(&ctx_); // incoherent: right for AO rays
    }
    void add(const Hit& h, const glm::vec3& dir, uint32_t pixel) {
        if (t_.screen_) { // the oracle: what the G-buffer holds decides, not the scene
            if (!t_.screen_->occluded(glm::vec3(h.px, h.py, h.pz), dir, t_.settings_.radius, pixel))
                ++t_.unoccluded_[pixel];
            ++traced;
            return;
        }
        RTCRayHit& r = batch_[filled_];
        r.ray.org_x = h.px, r.ray.org_y = h.py, r.ray.org_z = h.pz;
        r.ray.dir_x = dir.x, r.ray.dir_y = dir.y, r.ray.dir_z = dir.z;
        r.ray.tnear = 0.0f; // the origin is already offset off the surface
        r.ray.tfar = t_.settings_.radius;
        r.ray.time = 0.0f;
        r.ray.mask = 0xffffffffu;
        r.ray.id = 0;
        r.ray.flags = 0;
        r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        owner_[filled_] = pixel;
        if (++filled_ == kBatch) flush();
    }
    void flush() {
        if (!filled_) return;
        if (obscurance_) {
            rtcIntersect1M(t_.scene_.handle(), &ctx_, batch_, unsigned(filled_), sizeof(RTCRayHit));
            for (int k = 0; k < filled_; ++k) {
                const bool hit = batch_[k].hit.geomID != RTC_INVALID_GEOMETRY_ID;
                // Visibility of one ray under linear falloff: 1 - W(t) = t / R when it hits.
                const double w = hit ? std::clamp(double(batch_[k].ray.tfar) / t_.settings_.radius, 0.0, 1.0) : 1.0;
                t_.sumW_[owner_[k]] += w;
                t_.sumW2_[owner_[k]] += w * w;
            }
        } else {
            // rtcOccluded1M reads RTCRay records; RTCRayHit starts with one, so the stride skips the
            // hit part. tfar becomes -inf on an occluder.
            rtcOccluded1M(t_.scene_.handle(), &ctx_, &batch_[0].ray, unsigned(filled_), sizeof(RTCRayHit));
            for (int k = 0; k < filled_; ++k)
                if (batch_[k].ray.tfar >= 0.0f) ++t_.unoccluded_[owner_[k]];
        }
        traced += filled_;
        filled_ = 0;
    }
    long long traced = 0;

  private:
    ReferenceTracer& t_;
    bool obscurance_;
    RTCIntersectContext ctx_;
    alignas(64) RTCRayHit batch_[kBatch];
    uint32_t owner_[kBatch];
    int filled_ = 0;
};

bool ReferenceTracer::addSamples(int count, const std::atomic<bool>* cancel, const Progress& progress) {
    if (broken_) throw Error("reference: tracer was cancelled; start a new one");
    if (count <= 0) return true;
    const int first = done_;
    std::atomic<long long> rays{0};
    std::atomic<bool> stopped{false};
    const auto t0 = std::chrono::steady_clock::now();
    parallelRows(height_, threadCount(settings_.threads), [&](int y) {
        if (stopped.load(std::memory_order_relaxed) || (cancel && cancel->load(std::memory_order_relaxed))) {
            stopped = true;
            return;
        }
        RayBatch batch(*this);
        for (int x = 0; x < width_; ++x) {
            const size_t i = size_t(y) * width_ + x;
            if (geometry_[i] == 0.0f) continue;
            const Hit& h = hits_[i];
            const glm::vec3 n(h.nx, h.ny, h.nz);
            glm::vec3 t, b;
            orthonormalBasis(n, t, b);
            const uint32_t seed = pixelSeed(x, y);
            for (int s = first; s < first + count; ++s) {
                float lx, ly, lz;
                sampling::cosineHemisphere(sampling::sobol2D(uint32_t(s), seed), lx, ly, lz);
                batch.add(h, t * lx + b * ly + n * lz, uint32_t(i));
            }
        }
        batch.flush();
        rays.fetch_add(batch.traced);
    }, progress);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rays_ += rays.load();
    if (stopped) {
        broken_ = true;
        return false;
    }
    done_ += count;
    if (progress) progress(1.0);
    return true;
}

ReferenceImage ReferenceTracer::image() const {
    ReferenceImage img;
    img.width = width_;
    img.height = height_;
    img.samples = done_;
    img.depth = depth_;
    img.geometry = geometry_;
    img.ambiguous = ambiguous_;
    img.seconds = seconds_;
    img.aoRays = rays_;
    const size_t n = geometry_.size();
    img.ao.assign(n, 1.0f);
    img.stdErr.assign(n, 0.0f);
    if (done_ == 0) return img;
    const double N = done_;
    for (size_t i = 0; i < n; ++i) {
        if (geometry_[i] == 0.0f) continue;
        double mean, var;
        if (settings_.variant == ReferenceVariant::Obscurance) {
            mean = sumW_[i] / N;
            var = std::max(0.0, sumW2_[i] / N - mean * mean);
        } else {
            mean = double(unoccluded_[i]) / N;
            var = mean * (1.0 - mean); // Bernoulli
        }
        img.ao[i] = float(mean);
        // Standard error of an N-sample mean; the scrambled Sobol points do better than this
        // independent-sample bound, so it is conservative.
        img.stdErr[i] = float(std::sqrt(var / N));
    }
    return img;
}

long ReferenceImage::ambiguousPixels() const {
    long n = 0;
    for (float a : ambiguous)
        n += a > 0.0f ? 1 : 0;
    return n;
}

ReferenceImage traceReference(const EmbreeScene& scene, const Camera& camera, int width, int height,
                              const ReferenceSettings& settings, const ReferenceTracer::Progress& progress,
                              const std::atomic<bool>* cancel) {
    ReferenceTracer tracer(scene, camera, width, height, settings);
    if (!tracer.addSamples(settings.samples, cancel, progress)) throw Error("reference: cancelled");
    return tracer.image();
}

} // namespace ssao
