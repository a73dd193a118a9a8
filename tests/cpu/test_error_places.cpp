// The error by place (metrics/error_places.h) on views whose places are known by construction: an
// error planted at the frame's border, at a silhouette, in a concave crease and on a convex edge
// lands in that place and nowhere else, with the crease's opening angle and R in pixels binned.
#include "metrics/error_places.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace ssao;

namespace {

constexpr int kW = 96, kH = 64;
const double kTanHalf = std::tan(30.0 * M_PI / 180.0);

// View depth of the first hit of each pixel's ray with two planes through (0, 0, -10) whose normals
// are (+-sin a, 0, cos a) (facing the camera at the origin): the nearer hit is a concave corner
// (a pocket, opening 180 - 2a degrees), the farther a convex edge.
std::vector<float> vDepth(double aDeg, bool concave) {
    std::vector<float> d(size_t(kW) * kH);
    const double a = aDeg * M_PI / 180.0, aspect = double(kW) / kH;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const double dx = (2.0 * (x + 0.5) / kW - 1.0) * kTanHalf * aspect;
            double best = concave ? INFINITY : 0;
            for (double s : {1.0, -1.0}) {
                const double nx = s * std::sin(a), nz = std::cos(a);
                const double t = (nz * -10.0) / (nx * dx + nz * -1.0); // n . (t dir) = n . C, dir = (dx, dy, -1)
                best = concave ? std::min(best, t) : std::max(best, t);
            }
            d[size_t(y) * kW + x] = float(best); // t along (dx, dy, -1) is the view depth
        }
    return d;
}

PlaceMap mapOf(const std::vector<float>& depth, double radius) {
    return classifyPlaces({kW, kH, depth.data(), nullptr, kTanHalf, radius});
}

// Error of 0.3 on the pixels `where` picks, none elsewhere; returns the shares by place.
ErrorByPlace planted(const PlaceMap& m, bool (*where)(int x, int y)) {
    std::vector<float> ref(size_t(kW) * kH, 0.5f), test = ref;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (where(x, y)) test[size_t(y) * kW + x] += 0.3f;
    return errorByPlace(m, test.data(), ref.data());
}

double share(const ErrorByPlace& e, Place p) { return e.place[size_t(p)].sumSq / e.all.sumSq; }

// R that spans `px` pixels at depth `z`.
double radiusFor(double px, double z) { return px * z / (0.5 * kH / kTanHalf); }

} // namespace

TEST(ErrorPlaces, AnErrorAtTheBorderLandsInTheBorder) {
    const std::vector<float> flat(size_t(kW) * kH, 10.0f);
    const PlaceMap m = mapOf(flat, radiusFor(5, 10));
    EXPECT_NEAR(m.radiusPx[0], 5.0f, 1e-4f);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const bool border = std::min({x, kW - 1 - x, y, kH - 1 - y}) + 0.5 < 5.0;
            EXPECT_EQ(m.place[size_t(y) * kW + x], unsigned(border ? Place::Border : Place::Open)) << x << "," << y;
        }
    const ErrorByPlace e = planted(m, [](int x, int y) { return std::min({x, kW - 1 - x, y, kH - 1 - y}) < 3; });
    EXPECT_DOUBLE_EQ(share(e, Place::Border), 1.0);
    EXPECT_EQ(e.place[size_t(Place::Open)].sumSq, 0.0);
    EXPECT_EQ(e.radius[0].pixels, long(kW) * kH); // every pixel under 8 px
    const long ring = long(kW) * kH - long(kW - 6) * (kH - 6);  // the 3-pixel ring planted
    EXPECT_NEAR(e.place[size_t(Place::Border)].sumSigned, 0.3 * ring, 1e-3); // too bright: + bias
}

TEST(ErrorPlaces, AnErrorAtASilhouetteLandsInTheSilhouette) {
    std::vector<float> step(size_t(kW) * kH, 10.0f);
    for (int y = 0; y < kH; ++y)
        for (int x = kW / 2; x < kW; ++x) step[size_t(y) * kW + x] = 20.0f;
    const PlaceMap m = mapOf(step, radiusFor(2, 10)); // a 2-px R: a thin border
    const ErrorByPlace e = planted(m, [](int x, int y) { return std::abs(x - kW / 2) <= 1 && y > 4 && y < kH - 5; });
    EXPECT_DOUBLE_EQ(share(e, Place::Silhouette), 1.0);
    EXPECT_EQ(m.place[size_t(kH / 2) * kW + kW / 4], unsigned(Place::Open)); // away from the step
}

TEST(ErrorPlaces, AnErrorInAConcaveCreaseLandsInTheCreaseWithItsOpeningAngle) {
    const PlaceMap m = mapOf(vDepth(45, true), radiusFor(2, 10));
    const size_t centre = size_t(kH / 2) * kW + kW / 2;
    ASSERT_EQ(m.place[centre], unsigned(Place::Crease));
    EXPECT_NEAR(m.openingDeg[centre], 90.0f, 2.0f); // normals 90 degrees apart: a right-angled pocket
    EXPECT_EQ(m.place[size_t(kH / 2) * kW + kW / 4], unsigned(Place::Open)); // flat, away from the crease
    const ErrorByPlace e = planted(m, [](int x, int y) { return std::abs(x - kW / 2) <= 1 && y > 4 && y < kH - 5; });
    EXPECT_DOUBLE_EQ(share(e, Place::Crease), 1.0);
    EXPECT_EQ(e.opening[1].sumSq, e.place[size_t(Place::Crease)].sumSq); // 80-120 degrees
    // An acute pocket (normals 120 degrees apart: opening 60) bins below 80.
    const PlaceMap acute = mapOf(vDepth(60, true), radiusFor(2, 10));
    EXPECT_NEAR(acute.openingDeg[centre], 60.0f, 2.0f);
}

TEST(ErrorPlaces, AConvexEdgeIsNotACrease) {
    const PlaceMap m = mapOf(vDepth(45, false), radiusFor(2, 10));
    const size_t centre = size_t(kH / 2) * kW + kW / 2;
    EXPECT_EQ(m.place[centre], unsigned(Place::Convex));
    const ErrorByPlace e = planted(m, [](int x, int y) { return std::abs(x - kW / 2) <= 1 && y > 4 && y < kH - 5; });
    EXPECT_DOUBLE_EQ(share(e, Place::Convex), 1.0);
    EXPECT_EQ(e.place[size_t(Place::Crease)].pixels, 0);
}

TEST(ErrorPlaces, SkyAndExcludedPixelsCountNowhereAndTheJsonAddsUp) {
    std::vector<float> depth(size_t(kW) * kH, 10.0f), geometry(depth.size(), 1.0f), exclude(depth.size(), 0.0f);
    for (int x = 0; x < kW; ++x) geometry[size_t(x)] = 0.0f; // the top row: sky
    exclude[size_t(kH / 2) * kW + kW / 2] = 1.0f;
    const PlaceMap m = classifyPlaces({kW, kH, depth.data(), geometry.data(), kTanHalf, radiusFor(3, 10)});
    std::vector<float> ref(depth.size(), 0.4f), test(depth.size(), 0.5f);
    test[3] = NAN; // sky: not counted
    const ErrorByPlace e = errorByPlace(m, test.data(), ref.data(), nullptr, exclude.data());
    EXPECT_EQ(e.all.pixels, long(kW) * (kH - 1) - 1);
    const nlohmann::json j = errorByPlaceJson(e);
    double sum = 0;
    for (const auto& [name, p] : j["places"].items()) sum += p["share"].is_number() ? p["share"].get<double>() : 0.0;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_FALSE(j["places"]["open"].contains("technique_rmse")); // no oracle given
    EXPECT_THROW(classifyPlaces({kW, kH, nullptr, nullptr, kTanHalf, 1.0}), std::invalid_argument);
}
