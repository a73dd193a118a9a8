// Image error metrics of an AO image against a reference AO image (RMSE, MAE, bias, percentiles,
// PSNR of the sRGB encoding, SSIM, and an edge/interior split at depth discontinuities).
// Pure CPU code on plain float arrays: no GL, no glm, no Image type.
#pragma once
#include <vector>

namespace ssao {

// Single-channel float images, row-major, top row first, width*height values.
struct MetricsInput {
    int width = 0, height = 0;
    const float* test = nullptr;      // AO under test (linear, 1 = unoccluded); may hold NaN/inf
    const float* reference = nullptr; // reference AO (linear); finite by contract
    const float* geometry = nullptr;  // >0 where the pixel shows geometry (else sky); null = all geometry
    // Linear view depth (scene units) on geometry pixels; ignored on sky. May be null: then no edge
    // split (rmseEdge = rmseInterior = NaN, edgePixels = interiorPixels = 0).
    const float* depth = nullptr;
    const float* referenceStdErr = nullptr; // per-pixel standard error of the reference (null = 0)
    // >0 where the reference itself is ambiguous (ReferenceImage::ambiguous): such a pixel is left
    // out of every metric (its test value counts as equal to the reference in the whole-frame
    // PSNR and SSIM). Null = none.
    const float* exclude = nullptr;
};

struct MetricsOptions {
    int edgeRadiusPx = 3; // "within 3 px of a depth discontinuity" (Chebyshev distance)
    // 4-neighbours a,b form a discontinuity if |za-zb| > edgeRelDepth*min(za,zb), or one is geometry
    // and the other sky.
    float edgeRelDepth = 0.05f;
    double psnrCap = 100.0; // PSNR (dB) when MSE is 0, and upper bound otherwise; keeps JSON finite
};

struct ErrorMetrics {
    long pixels = 0, geometryPixels = 0, edgePixels = 0, interiorPixels = 0;
    long excludedPixels = 0; // geometry pixels left out (MetricsInput::exclude); not in geometryPixels
    // Test pixels (over the whole frame) that are NaN or ±inf. Every metric treats such a value as
    // 1.0 (unoccluded: what an R8 target would show, white), so the other numbers stay finite.
    long nonFinite = 0;
    // Over geometry pixels, linear AO (all 0 when there is no geometry).
    // bias = mean(test - reference): + means under-occlusion (too bright).
    double rmse = 0, mae = 0, bias = 0;
    double p99Abs = 0, maxAbs = 0; // 99th percentile (linear interpolation, as numpy), max of |test-ref|
    double psnrGeometrySrgb = 0;   // PSNR (peak 1) of sRGB-encoded AO over geometry pixels (cap if none)
    double psnrFullSrgb = 0;       // XeGTAO's headline: sRGB-encoded, whole frame including sky
    // RMSE (linear) over geometry pixels within edgeRadiusPx of a discontinuity / over the rest.
    // NaN when that set is empty (or depth is null): there is no meaningful value, and 0 would lie.
    double rmseEdge = 0, rmseInterior = 0;
    double ssim = 0; // mean SSIM (Wang et al. 2004) of the sRGB-encoded AO, whole frame
    // RMS of referenceStdErr over geometry pixels: the reference's own noise floor.
    double referenceNoise = 0;
};

// IEC 61966-2-1 sRGB encoding (piecewise: 12.92 v below 0.0031308, else 1.055 v^(1/2.4) - 0.055),
// input clamped to [0,1]. NaN stays NaN.
float linearToSrgb(float v);

// SSIM, Wang, Bovik, Sheikh, Simoncelli 2004: 11x11 Gaussian window sigma 1.5 (normalised), K1=0.01,
// K2=0.03, L=1, C1=(K1 L)^2, C2=(K2 L)^2, population (not sample) covariance, mean over the pixels whose
// full window lies inside the image (like skimage's structural_similarity(gaussian_weights=True,
// sigma=1.5, use_sample_covariance=False, data_range=1)). In a dimension smaller than 11 px every
// position counts, with the window clipped to the image and its weights renormalised. Separable,
// O(w*h*11). Empty images give 1; non-finite inputs propagate into the result.
double ssim(const float* a, const float* b, int width, int height);

// Mask (1 = edge) of the geometry pixels within radiusPx (Chebyshev) of a depth discontinuity (see
// MetricsOptions): the two pixels of a discontinuous 4-neighbour pair are at distance 0. Sky pixels
// are never flagged. geometry null = all geometry; depth null = only geometry/sky borders count.
std::vector<unsigned char> edgeMask(const float* geometry, const float* depth, int width, int height,
                                    int radiusPx, float relDepth);

// All metrics of `in` (see ErrorMetrics). Throws std::invalid_argument when test or reference is null
// for a non-empty image, or a size is negative.
ErrorMetrics computeErrorMetrics(const MetricsInput& in, const MetricsOptions& opt = {});

} // namespace ssao
