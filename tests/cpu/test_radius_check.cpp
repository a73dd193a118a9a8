// The scene radius against what the view shows (metrics/radius_check.h): a close-up of a large
// scene is named with the world radius that matches the view; a framed scene, a world or screen
// radius and an empty view are not.
#include "metrics/radius_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace ssao;

namespace {
Camera camera(float fov = 60.0f) {
    Camera c;
    c.fovYDeg = fov;
    return c;
}
AoSettings sceneRadius(float fraction = 0.05f) {
    AoSettings a;
    a.radiusMode = RadiusMode::Scene;
    a.radiusScene = fraction;
    return a;
}
} // namespace

TEST(ViewRadius, ACloseUpOfALargeSceneIsNamedWithTheRadiusThatMatchesTheView) {
    // Half the pixels sky, the rest at depths 1, 2 and 3: median 2 (of the geometry), 60 degrees: the
    // view is 2 x 2 tan 30 = 2.309 tall, 16:9 so that is its shorter side; diagonal 40: R 2 = 87 % of it.
    std::vector<float> depth;
    for (int i = 0; i < 300; ++i)
        depth.push_back(i % 2 ? 0.0f : float(1 + (i / 2) % 3));
    depth.push_back(NAN);
    const ViewRadiusCheck c = checkViewRadius(depth.data(), depth.size(), camera(), 16.0 / 9.0, sceneRadius(), 40.0);
    EXPECT_TRUE(c.tooLarge);
    EXPECT_NEAR(c.radius, 2.0, 1e-6);
    EXPECT_EQ(c.medianDepth, 2.0);
    EXPECT_NEAR(c.viewExtent, 2.0 * c.medianDepth * std::tan(M_PI / 6.0), 1e-6);
    EXPECT_NEAR(c.suggested, 0.05 * c.viewExtent, 0.001);
    const std::string m = c.message();
    std::printf("%s\n", m.c_str());
    EXPECT_NE(m.find("--set ao.radius=0.115"), std::string::npos) << m;
    EXPECT_NE(m.find("the AO radius 2 units"), std::string::npos) << m;
    EXPECT_NE(m.find("2.309 units across"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line";
}

TEST(ViewRadius, AFramedSceneAWorldOrScreenRadiusAndAnEmptyViewAreNotNamed) {
    const std::vector<float> far(100, 20.0f); // 23 units tall: R 2 is 9 % of it
    EXPECT_FALSE(checkViewRadius(far.data(), far.size(), camera(), 1.5, sceneRadius(), 40.0).tooLarge);
    const std::vector<float> near(100, 1.0f);
    EXPECT_TRUE(checkViewRadius(near.data(), near.size(), camera(), 1.5, sceneRadius(), 40.0).tooLarge);
    AoSettings world = sceneRadius(), screen = sceneRadius();
    world.radiusMode = RadiusMode::World, screen.radiusMode = RadiusMode::Screen;
    EXPECT_FALSE(checkViewRadius(near.data(), near.size(), camera(), 1.5, world, 40.0).tooLarge) << "the user's own radius";
    EXPECT_FALSE(checkViewRadius(near.data(), near.size(), camera(), 1.5, screen, 40.0).tooLarge);
    EXPECT_EQ(checkViewRadius(near.data(), near.size(), camera(), 1.5, world, 40.0).message(), "");
    const std::vector<float> sky(100, 0.0f);
    const ViewRadiusCheck none = checkViewRadius(sky.data(), sky.size(), camera(), 1.5, sceneRadius(), 40.0);
    EXPECT_FALSE(none.tooLarge);
    EXPECT_EQ(none.medianDepth, 0.0);
    // Just under and just over the limit: a portrait view's shorter side is its width.
    const double tall = 2.0 * std::tan(M_PI / 6.0), wide = tall * 0.5, limit = kViewRadiusLimit * wide / 0.05;
    EXPECT_FALSE(checkViewRadius(near.data(), near.size(), camera(), 0.5, sceneRadius(), 0.99 * limit).tooLarge);
    EXPECT_TRUE(checkViewRadius(near.data(), near.size(), camera(), 0.5, sceneRadius(), 1.01 * limit).tooLarge);
}

TEST(ViewRadius, AnOrthographicViewSpansTheSameAtEveryDepth) {
    Camera c = camera();
    c.projectionKind = Projection::Orthographic;
    c.eye = {0, 0, 10}, c.target = {0, 0, 0}; // half height 10 tan 30 = 5.77
    const std::vector<float> near(10, 0.5f);
    const ViewRadiusCheck v = checkViewRadius(near.data(), near.size(), c, 2.0, sceneRadius(), 40.0);
    EXPECT_NEAR(v.viewExtent, 2.0 * c.orthoHalfHeight(), 1e-5);
    EXPECT_FALSE(v.tooLarge);
}
