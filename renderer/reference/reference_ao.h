// Ray-traced reference AO on the CPU (Embree), defined as Intel XeGTAO's ground truth so errors
// are comparable with its published figures:
//   AO(p) = (1/pi) * integral over the hemisphere of V_R(p, w) (n . w) dw
// one primary ray through each pixel centre with the rasteriser's camera (near/far included); n =
// the renormalised interpolated vertex normal, face-forwarded like the G-buffer's; V_R = 1 when a
// ray leaves p in direction w and hits nothing within the world radius R. Cosine-weighted samples
// (pdf = cos/pi) make the estimator the fraction of unoccluded rays. No falloff, no bounces, sky
// pixels = 1, every triangle of the scene occludes (in view or not, either side).
// The "obscurance" variant weights an occluded ray by its hit distance, W = max(0, 1 - t/R)
// (unoccluded = 1), for analysis against techniques that model a falloff.
#pragma once
#include "reference/embree_scene.h"
#include "reference/screen_layers.h"
#include "scene/camera.h"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

enum class ReferenceVariant { Visibility, Obscurance };
const char* variantName(ReferenceVariant v);               // "visibility" | "obscurance"
ReferenceVariant parseVariant(const std::string& name);    // throws ssao::Error naming the choices

// What decides whether an AO ray is blocked: the scene (the ground truth), or only what a G-buffer
// holds (the screen-space oracle, screen_layers.h): the same integral, R and rays, so the oracle's
// error against the truth is what the screen cannot see, and a technique's error against the
// oracle is what its settings can still fix.
enum class ReferenceVisibility { Scene, Screen };

struct ReferenceSettings {
    float radius = 0.5f; // R, scene units: the same world radius the SSAO technique is given
    int samples = 512;   // rays per pixel (XeGTAO accumulates 512)
    ReferenceVariant variant = ReferenceVariant::Visibility;
    int threads = 0;     // 0 = every hardware thread; the result does not depend on it
    ReferenceVisibility visibility = ReferenceVisibility::Scene;
    // The oracle's screen (visibility = Screen): 1 depth layer (a G-buffer) or 2: the first
    // layer's back face when the view ray meets one next (its true thickness, as a back-face depth
    // buffer holds it), else the nearest surface at least `layerSeparation` x R behind the first (a
    // deep G-buffer; Mara, McGuire, Nowrouzezahrai and Luebke 2016). A front surface is solid for
    // `thickness` x R behind itself (infinite: the height field GTAO assumes) or down to its back face.
    int layers = 1;
    float thickness = 1.0f; // x R; 1 R: the best of 0.25..inf on CornellBox (README, "The screen-space oracle")
    float layerSeparation = 0.1f;
    int guardBand = 0; // pixels the oracle's G-buffer holds beyond each edge of the frame
};

// A reference frame: single-channel images, row-major, top row first.
struct ReferenceImage {
    int width = 0, height = 0;
    int samples = 0;               // rays per pixel accumulated
    std::vector<float> ao;         // estimate, 1 = unoccluded; sky = 1
    std::vector<float> stdErr;     // per-pixel standard error of the estimate (sky = 0)
    std::vector<float> depth;      // primary hit's linear view depth (scene units), sky = 0
    std::vector<float> geometry;   // 1 where the primary ray hit, else 0
    // 1 where the truth itself is ambiguous: a surface passes within a few float ULPs of the
    // secondary rays' origin (two faces in one place, ray_offset.h), so whether it occludes is
    // decided by rounding. Error metrics leave these pixels out and say how many (MetricsInput).
    std::vector<float> ambiguous;
    long ambiguousPixels() const;
    double seconds = 0;            // tracing wall time (AO rays)
    long long aoRays = 0;          // AO rays traced
    double raysPerSecond() const { return seconds > 0 ? double(aoRays) / seconds : 0.0; }
};

// Traces a view progressively: primary hits once, then batches of samples per pixel. Sample i of a
// pixel is seeded by (pixel, i) alone, so the result is bit-identical for any thread count and any
// split into batches.
class ReferenceTracer {
  public:
    using Progress = std::function<void(double fraction)>;

    ReferenceTracer(const EmbreeScene& scene, const Camera& camera, int width, int height,
                    const ReferenceSettings& settings);

    // Adds `count` samples to every pixel. Returns false when `cancel` was raised; the tracer is
    // then unusable (rows hold different sample counts).
    bool addSamples(int count, const std::atomic<bool>* cancel = nullptr, const Progress& progress = {});
    int samplesDone() const { return done_; }
    ReferenceImage image() const;

  private:
    struct Hit {
        float px, py, pz; // offset ray origin
        float nx, ny, nz; // shading normal (unit, facing the viewer's side)
    };

    class RayBatch;
    // The primary hit of pixel i (ray direction d): offset origin, normal, coincident-face flag.
    void storeHit(size_t i, const RTCRayHit& rh, const glm::vec3& d);
    // The deep G-buffer's second layer at pixel i: the nearest surface at least the separation
    // behind the first hit `p` along the primary ray d.
    void storeSecondLayer(int x, int y, const glm::vec3& p, const glm::vec3& d, float far);
    // The oracle's guard band: the first (and second) layer of the pixels beyond the frame's edges.
    void traceGuardBand(const Camera& camera);
    // How the oracle's G-buffer holds a surface of triangle primID: MASK triangles are sheets.
    SurfaceKind kindOf(unsigned primID) const;

    const EmbreeScene& scene_;
    std::unique_ptr<ScreenLayers> screen_; // the oracle's G-buffer (visibility = Screen)
    int width_, height_;
    ReferenceSettings settings_;
    std::vector<Hit> hits_;
    std::vector<float> depth_, geometry_, ambiguous_;
    std::vector<uint32_t> unoccluded_; // visibility: rays that escaped
    std::vector<double> sumW_, sumW2_; // obscurance: sum of weights and of squares
    int done_ = 0;
    bool broken_ = false;
    double seconds_ = 0;
    long long rays_ = 0;
};

// The whole reference in one call (what the CLI and benchmarks use without a cache).
ReferenceImage traceReference(const EmbreeScene& scene, const Camera& camera, int width, int height,
                              const ReferenceSettings& settings, const ReferenceTracer::Progress& progress = {},
                              const std::atomic<bool>* cancel = nullptr);

} // namespace ssao
