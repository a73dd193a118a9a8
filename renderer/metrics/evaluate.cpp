#include "metrics/evaluate.h"

#include "reference/reference_cache.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ssao {

Evaluation evaluate(const Image& ao, const ReferenceImage& ref, const MetricsOptions& opt) {
    Evaluation e;
    const int w = ref.width, h = ref.height;
    e.test = Image{w, h, 1, std::vector<float>(size_t(w) * h)};
    e.error = Image{w, h, 1, std::vector<float>(size_t(w) * h, 0.0f)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const float v = ao.at(mapPixel(x, w, ao.width), mapPixel(y, h, ao.height));
            e.test.data[i] = v;
            if (ref.geometry[i] > 0.0f) e.error.data[i] = v - ref.ao[i];
        }
    MetricsInput in;
    in.width = w;
    in.height = h;
    in.test = e.test.data.data();
    in.reference = ref.ao.data();
    in.geometry = ref.geometry.data();
    in.depth = ref.depth.data();
    in.referenceStdErr = ref.stdErr.data();
    if (ref.ambiguous.size() == ref.ao.size()) in.exclude = ref.ambiguous.data();
    e.metrics = computeErrorMetrics(in, opt);
    return e;
}

ErrorShares splitShares(const Evaluation& technique, const ReferenceImage& oracle, const ReferenceImage& truth) {
    SplitImages in;
    in.width = truth.width, in.height = truth.height;
    if (technique.test.width != truth.width || technique.test.height != truth.height || oracle.width != truth.width ||
        oracle.height != truth.height)
        throw std::invalid_argument("splitShares: the AO, the oracle and the truth are of different sizes");
    in.test = technique.test.data.data();
    in.oracle = oracle.ao.data();
    in.reference = truth.ao.data();
    in.geometry = truth.geometry.data();
    if (truth.ambiguous.size() == truth.ao.size()) in.exclude = truth.ambiguous.data();
    return errorShares(in);
}

PlaceMap placesOf(const ReferenceImage& ref, const Camera& camera, double radius) {
    PlaceView v{ref.width, ref.height, ref.depth.data(), ref.geometry.data(),
                std::tan(0.5 * double(camera.fovYDeg) * 3.14159265358979323846 / 180.0), radius};
    if (camera.orthographic()) v.orthoHalfHeight = camera.orthoHalfHeight();
    return classifyPlaces(v);
}

ErrorByPlace errorByPlace(const Evaluation& e, const ReferenceImage& ref, const PlaceMap& places, const ReferenceImage* oracle) {
    if (e.test.width != ref.width || e.test.height != ref.height || places.width != ref.width ||
        (oracle && (oracle->width != ref.width || oracle->height != ref.height)))
        throw std::invalid_argument("errorByPlace: the AO, the places, the oracle and the truth are of different sizes");
    return errorByPlace(places, e.test.data.data(), ref.ao.data(), oracle ? oracle->ao.data() : nullptr,
                        ref.ambiguous.size() == ref.ao.size() ? ref.ambiguous.data() : nullptr);
}

Image errorHeatmap(const Image& error, const std::vector<float>& geometry, float range) {
    Image out{error.width, error.height, 3, std::vector<float>(size_t(error.width) * error.height * 3)};
    for (size_t i = 0; i < size_t(error.width) * error.height; ++i) {
        float r = 0.5f, g = 0.5f, b = 0.5f;
        if (geometry[i] > 0.0f) {
            const float e = error.data[i];
            if (!std::isfinite(e)) {
                r = 1.0f, g = 0.0f, b = 1.0f; // magenta: the AO itself was NaN/inf
            } else {
                const float t = std::clamp(e / range, -1.0f, 1.0f);
                // white → red for t > 0, white → blue for t < 0
                r = t < 0.0f ? 1.0f + t : 1.0f;
                b = t > 0.0f ? 1.0f - t : 1.0f;
                g = 1.0f - std::abs(t);
            }
        }
        out.data[3 * i] = r, out.data[3 * i + 1] = g, out.data[3 * i + 2] = b;
    }
    return out;
}

namespace {
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
} // namespace

nlohmann::json metricsJson(const ErrorMetrics& m, const ReferenceImage& ref, const ReferenceSettings& s) {
    return {{"rmse", num(m.rmse)},
            {"mae", num(m.mae)},
            {"bias", num(m.bias)},
            {"p99_abs", num(m.p99Abs)},
            {"max_abs", num(m.maxAbs)},
            {"psnr_geometry_srgb", num(m.psnrGeometrySrgb)},
            {"psnr_full_srgb", num(m.psnrFullSrgb)},
            {"rmse_edge", num(m.rmseEdge)},
            {"rmse_interior", num(m.rmseInterior)},
            {"ssim", num(m.ssim)},
            {"nonfinite", m.nonFinite},
            {"pixels", {{"all", m.pixels}, {"geometry", m.geometryPixels}, {"edge", m.edgePixels},
                        {"interior", m.interiorPixels}, {"ambiguous", m.excludedPixels}}},
            {"reference",
             {{"definition", kReferenceDefinition},
              {"variant", variantName(s.variant)},
              {"radius", s.radius},
              {"rays_per_pixel", ref.samples},
              {"ambiguous_pixels", ref.ambiguousPixels()},
              {"noise_rms", num(m.referenceNoise)},
              {"trace_seconds", ref.seconds},
              {"mrays_per_second", ref.raysPerSecond() * 1e-6}}},
            {"notes", "geometry pixels are the reference's primary hits; bias = mean(test - reference), + = "
                      "too bright; edge = within 3 px of a depth discontinuity; PSNR and SSIM on sRGB-encoded AO; "
                      "ambiguous = pixels where a surface lies within a few float ULPs of the reference's ray "
                      "origin (coincident faces: the truth is decided by rounding), left out of every metric"}};
}

} // namespace ssao
