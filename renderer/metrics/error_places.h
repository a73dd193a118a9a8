// Where the error lives: each geometry pixel of a view put in one place, and the squared error
// against the truth summed by place, so a change can be aimed at the largest part and its effect seen.
// Places, by priority (a pixel is in the first that holds):
//   border     - nearer the frame's edge than R in pixels: some of its taps fall off the screen;
//   silhouette - within a few pixels of a depth discontinuity (error_metrics.h's edge rule);
//   crease     - within a few pixels of a concave normal discontinuity on one surface (by its
//                opening angle: the angle between the two faces, 180 degrees flat);
//   convex     - the same at a convex one (an outer edge, which occludes nothing);
//   open       - the rest.
// And, over every pixel, by R in pixels at the pixel (< 8, 8-16, > 16). Normals come from the view
// depth (positions reconstructed with the camera's vertical field of view). Pure CPU code.
#pragma once
#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace ssao {

enum class Place : unsigned char { Border, Silhouette, Crease, Convex, Open };
constexpr int kPlaces = 5;
const char* placeName(Place p);

struct PlaceView {
    int width = 0, height = 0;
    const float* depth = nullptr;    // linear view depth on geometry pixels (scene units)
    const float* geometry = nullptr; // > 0 where the pixel shows geometry; null = all
    double tanHalfFovY = 0;          // tan(vertical field of view / 2)
    double radius = 0;               // R, scene units
    double orthoHalfHeight = 0;      // > 0: an orthographic view of this half height (scene units)
};

struct PlaceOptions {
    int silhouettePx = 2;           // "within 2 px" of a depth discontinuity (Chebyshev)
    float silhouetteRelDepth = 0.05f;
    int creasePx = 2;               // "within 2 px" of a normal discontinuity
    float creaseMinDeg = 20.0f;     // normals further apart than this make a crease or an edge
};

struct PlaceMap {
    int width = 0, height = 0;
    std::vector<unsigned char> place;  // Place per pixel; 255 on sky
    std::vector<float> radiusPx;       // R in pixels at the pixel (0 on sky)
    std::vector<float> openingDeg;     // a crease's opening angle (degrees), 0 elsewhere
};

// Throws std::invalid_argument on a missing depth or a non-positive size, field of view or R.
PlaceMap classifyPlaces(const PlaceView& v, const PlaceOptions& o = {});

struct PlaceStats {
    long pixels = 0;
    double sumSq = 0;        // sum of (test - reference)^2
    double sumSigned = 0;    // sum of (test - reference): + where too bright (under-occluded)
    double sumSqOracle = 0;  // sum of (test - oracle)^2: the technique's own part (0 without an oracle)
};

constexpr int kRadiusBins = 3;  // R in pixels: < 8, 8-16, > 16
constexpr int kOpeningBins = 3; // a crease's opening angle: < 80, 80-120, > 120 degrees

struct ErrorByPlace {
    std::array<PlaceStats, kPlaces> place{};
    std::array<PlaceStats, kRadiusBins> radius{};
    std::array<PlaceStats, kOpeningBins> opening{};
    PlaceStats all;
    bool hasOracle = false;
};

// Single-channel images at the map's size. test: NaN/inf count as 1.0, as every metric does;
// oracle and exclude may be null.
ErrorByPlace errorByPlace(const PlaceMap& m, const float* test, const float* reference, const float* oracle = nullptr,
                          const float* exclude = nullptr);

// Sums of several views (a bench row over its views).
void accumulate(ErrorByPlace& into, const ErrorByPlace& v);

// {"how_to_read", "places": {name: {pixels, pixel_share, rmse, bias, share, technique_rmse}}, "radius_px":
// {...}, "crease_opening_deg": {...}}: share = that place's part of the whole view's squared error.
nlohmann::json errorByPlaceJson(const ErrorByPlace& e);

// The raw sums, for results.json (a merge adds views up again): {"has_oracle", NAME: [pixels, sum of
// squares, signed sum, sum of squares against the oracle]} for every place and bin. The reader throws
// std::invalid_argument naming the field when one is missing, not four numbers, or negative.
nlohmann::json placeSumsJson(const ErrorByPlace& e);
ErrorByPlace placeSumsFromJson(const nlohmann::json& j);

// One line: each place's share of the squared error, its RMSE and its pixels' share.
std::string errorByPlaceLine(const ErrorByPlace& e);

} // namespace ssao
