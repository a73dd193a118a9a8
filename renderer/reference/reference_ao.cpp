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

} // namespace

ReferenceTracer::ReferenceTracer(const EmbreeScene& scene, const Camera& camera, int width, int height,
                                 const ReferenceSettings& settings)
    : scene_(scene), width_(width), height_(height), settings_(settings) {
    if (width <= 0 || height <= 0) throw Error("reference: empty image size");
    if (!(settings.radius > 0.0f) || !std::isfinite(settings.radius))
        throw Error("reference: the radius must be a positive finite number of scene units");
    if (settings.samples < 1) throw Error("reference: at least one ray per pixel is needed");
    validateCamera(camera);
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

    // The rasteriser's camera (glm::lookAt + Camera::projection): pixel centre (x + 0.5, y + 0.5),
    // y from the top, maps to NDC (2(x+0.5)/W - 1, 1 - 2(y+0.5)/H).
    const glm::dvec3 eye(camera.eye);
    const glm::dvec3 fwd = glm::normalize(glm::dvec3(camera.target) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(fwd, glm::dvec3(camera.up)));
    const glm::dvec3 up = glm::cross(right, fwd);
    const double tanHalf = std::tan(glm::radians(double(camera.fovYDeg)) * 0.5);
    const double aspect = double(width) / double(height);
    const bool ortho = camera.orthographic();
    const double orthoHalf = glm::length(glm::dvec3(camera.target) - eye) * tanHalf;
    const Scene& sc = scene.scene();

    parallelRows(height, threadCount(settings.threads), [&](int y) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        for (int x = 0; x < width; ++x) {
            const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / height;
            // Orthographic: parallel rays from the eye plane, the view spanning +-orthoHalf.
            const glm::dvec3 d = ortho ? fwd : glm::normalize(fwd + right * (nx * tanHalf * aspect) + up * (ny * tanHalf));
            const glm::dvec3 org = ortho ? eye + right * (nx * orthoHalf * aspect) + up * (ny * orthoHalf) : eye;
            const double cosFwd = glm::dot(d, fwd);
            alignas(16) RTCRayHit rh{};
            rh.ray.org_x = float(org.x), rh.ray.org_y = float(org.y), rh.ray.org_z = float(org.z);
            rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
            // Only what lies between the clip planes is rasterised (view depth = t * cosFwd).
            rh.ray.tnear = float(camera.nearZ / cosFwd);
            rh.ray.tfar = std::isinf(camera.farZ) ? INFINITY : float(camera.farZ / cosFwd);
            rh.ray.mask = 0xffffffffu;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene.handle(), &ctx, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            const size_t i = size_t(y) * width + x;
            const uint32_t* tri = &sc.indices[size_t(rh.hit.primID) * 3];
            const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
            // Barycentric position: exact to the triangle's precision, unlike org + t * dir.
            const glm::vec3 p = w * sc.vertices[tri[0]].position + u * sc.vertices[tri[1]].position +
                                v * sc.vertices[tri[2]].position;
            glm::vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
            const float ngLen = glm::length(ng);
            ng = ngLen > 0.0f ? ng / ngLen : -glm::vec3(d);
            if (glm::dot(glm::dvec3(ng), d) > 0.0) ng = -ng; // the face the camera sees
            glm::vec3 n = w * sc.vertices[tri[0]].normal + u * sc.vertices[tri[1]].normal +
                          v * sc.vertices[tri[2]].normal;
            const float nLen = glm::length(n);
            n = nLen > 1e-10f ? n / nLen : ng; // interpolated normals are shorter than 1
            if (glm::dot(n, ng) < 0.0f) n = -n; // as the G-buffer: shade the side we see
            float scale = 0.0f;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 a = glm::abs(sc.vertices[tri[k]].position);
                scale = std::max({scale, a.x, a.y, a.z});
            }
            const glm::vec3 o = offsetRayOrigin(backOffTowardEye(p, -glm::vec3(d), scale), ng);
            hits_[i] = Hit{o.x, o.y, o.z, n.x, n.y, n.z};
            // Coincident faces: a short probe along the geometric and the shading normal (the
            // shortest way to a parallel twin) that hits within a few ULPs - of the hit's own
            // coordinates or of the primary distance, whichever is coarser: a camera far away
            // orders two faces closer than its ULPs at random, and the offset above clears only
            // the hit's.
            const float coarse = std::max(scale, rh.ray.tfar);
            for (const glm::vec3& dir : {ng, n}) {
                alignas(16) RTCRay probe{};
                probe.org_x = o.x, probe.org_y = o.y, probe.org_z = o.z;
                probe.dir_x = dir.x, probe.dir_y = dir.y, probe.dir_z = dir.z;
                probe.tnear = 0.0f;
                probe.tfar = coincidenceDistance(coarse);
                probe.mask = 0xffffffffu;
                RTCIntersectContext near;
                rtcInitIntersectContext(&near);
                rtcOccluded1(scene.handle(), &near, &probe);
                if (probe.tfar < 0.0f) ambiguous_[i] = 1.0f; // Embree sets tfar = -inf on a hit
            }
            depth_[i] = float(double(rh.ray.tfar) * cosFwd);
            geometry_[i] = 1.0f;
        }
    }, {});
}

bool ReferenceTracer::addSamples(int count, const std::atomic<bool>* cancel, const Progress& progress) {
    if (broken_) throw Error("reference: tracer was cancelled; start a new one");
    if (count <= 0) return true;
    const int first = done_;
    const bool obscurance = settings_.variant == ReferenceVariant::Obscurance;
    const float radius = settings_.radius;
    std::atomic<long long> rays{0};
    std::atomic<bool> stopped{false};
    const auto t0 = std::chrono::steady_clock::now();

    parallelRows(height_, threadCount(settings_.threads), [&](int y) {
        if (stopped.load(std::memory_order_relaxed) || (cancel && cancel->load(std::memory_order_relaxed))) {
            stopped = true;
            return;
        }
        alignas(64) RTCRayHit batch[kBatch];
        uint32_t owner[kBatch];
        int filled = 0;
        long long traced = 0;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx); // incoherent: right for AO rays
        auto flush = [&] {
            if (!filled) return;
            if (obscurance) {
                rtcIntersect1M(scene_.handle(), &ctx, batch, unsigned(filled), sizeof(RTCRayHit));
                for (int k = 0; k < filled; ++k) {
                    const bool hit = batch[k].hit.geomID != RTC_INVALID_GEOMETRY_ID;
                    // Visibility of one ray under linear falloff: 1 - W(t) = t / R when it hits.
                    const double w = hit ? std::clamp(double(batch[k].ray.tfar) / radius, 0.0, 1.0) : 1.0;
                    sumW_[owner[k]] += w;
                    sumW2_[owner[k]] += w * w;
                }
            } else {
                // rtcOccluded1M reads RTCRay records; RTCRayHit starts with one, so the stride
                // skips the hit part. tfar becomes -inf on an occluder.
                rtcOccluded1M(scene_.handle(), &ctx, &batch[0].ray, unsigned(filled), sizeof(RTCRayHit));
                for (int k = 0; k < filled; ++k)
                    if (batch[k].ray.tfar >= 0.0f) ++unoccluded_[owner[k]];
            }
            traced += filled;
            filled = 0;
        };
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
                const glm::vec3 dir = t * lx + b * ly + n * lz;
                RTCRayHit& r = batch[filled];
                r.ray.org_x = h.px, r.ray.org_y = h.py, r.ray.org_z = h.pz;
                r.ray.dir_x = dir.x, r.ray.dir_y = dir.y, r.ray.dir_z = dir.z;
                r.ray.tnear = 0.0f; // the origin is already offset off the surface
                r.ray.tfar = radius;
                r.ray.time = 0.0f;
                r.ray.mask = 0xffffffffu;
                r.ray.id = 0;
                r.ray.flags = 0;
                r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                owner[filled] = uint32_t(i);
                if (++filled == kBatch) flush();
            }
        }
        flush();
        rays.fetch_add(traced);
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
