// An AO frame judged against its ray-traced reference: the metrics (error_metrics.h), the signed
// error image and its heat map, and the JSON block metrics.json, the bench and the app report.
#pragma once
#include "base/image.h"
#include "metrics/error_metrics.h"
#include "metrics/error_places.h"
#include "metrics/error_split.h"
#include "reference/reference_ao.h"
#include "scene/camera.h"

#include <nlohmann/json.hpp>

namespace ssao {

struct Evaluation {
    ErrorMetrics metrics;
    Image test;  // the AO under test at the reference's size (nearest texel when AO is reduced)
    Image error; // signed error, test - reference (+ = too bright, under-occluded); sky 0
};

// `ao`: channel 0 of the AO under test, any resolution covering the same view.
Evaluation evaluate(const Image& ao, const ReferenceImage& ref, const MetricsOptions& opt = {});

// The additive split (error_split.h) of one view: `technique` is the AO judged against `oracle`
// (its test image at the oracle's size), `truth` the reference of the same view and size.
ErrorShares splitShares(const Evaluation& technique, const ReferenceImage& oracle, const ReferenceImage& truth);

// Where each pixel of `ref`'s view is (error_places.h): `camera` gives its projection, `radius` R.
PlaceMap placesOf(const ReferenceImage& ref, const Camera& camera, double radius);

// The error of `e` (its test image, at ref's size) by place; `oracle` (the same size) may be null.
ErrorByPlace errorByPlace(const Evaluation& e, const ReferenceImage& ref, const PlaceMap& places,
                          const ReferenceImage* oracle = nullptr);

// Diverging heat map of a signed error: blue where the AO is too dark (over-occlusion), red where
// it is too bright, white at 0; saturates at ±range. Sky (mask 0) is mid grey.
Image errorHeatmap(const Image& error, const std::vector<float>& geometry, float range = 0.25f);

// {"rmse", ..., "reference": {definition, variant, radius, rays, noise_rms, ...}}; NaN → null.
nlohmann::json metricsJson(const ErrorMetrics& m, const ReferenceImage& ref, const ReferenceSettings& s);

} // namespace ssao
