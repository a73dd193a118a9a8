// The camera's lens and depth mapping (scene/camera.h): reversed-Z and orthographic projections,
// as matrices, as validation, and through --camera and preset JSON.
#include "scene/camera.h"
#include "settings/preset.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

using namespace ssao;
using ssaotest::errorOf;

namespace {
// z_ndc of the view-space point (0, 0, z).
float ndcDepth(const glm::mat4& p, float z) {
    const glm::vec4 c = p * glm::vec4(0.0f, 0.0f, z, 1.0f);
    return c.z / c.w;
}
glm::vec2 ndcXY(const glm::mat4& p, glm::vec3 v) {
    const glm::vec4 c = p * glm::vec4(v, 1.0f);
    return glm::vec2(c) / c.w;
}
} // namespace

TEST(CameraLens, ReversedDepthMapsNearToOneAndFarToZero) {
    Camera c;
    c.nearZ = 0.1f, c.farZ = 100.0f, c.depth = DepthMode::Reversed;
    const glm::mat4 p = c.projection(16.0f / 9.0f);
    EXPECT_NEAR(ndcDepth(p, -0.1f), 1.0f, 1e-6f);
    EXPECT_NEAR(ndcDepth(p, -100.0f), 0.0f, 1e-6f);
    EXPECT_GT(ndcDepth(p, -1.0f), ndcDepth(p, -2.0f)); // nearer is larger: the test is GREATER
    // x and y are the standard perspective's: only depth changes.
    Camera s = c;
    s.depth = DepthMode::Standard;
    const glm::vec3 v(0.3f, -0.2f, -3.0f);
    EXPECT_NEAR(glm::distance(ndcXY(p, v), ndcXY(s.projection(16.0f / 9.0f), v)), 0.0f, 1e-6f);
    // Standard depth: [-1, 1], -1 at near.
    EXPECT_NEAR(ndcDepth(s.projection(1.0f), -0.1f), -1.0f, 1e-5f);

    // An infinite far plane: near still maps to 1, depth falls as near / z toward 0, never below.
    c.farZ = INFINITY;
    const glm::mat4 pi = c.projection(1.0f);
    EXPECT_NEAR(ndcDepth(pi, -0.1f), 1.0f, 1e-6f);
    EXPECT_NEAR(ndcDepth(pi, -1e6f), 1e-7f, 1e-12f);
    EXPECT_GT(ndcDepth(pi, -1e30f), 0.0f);
    // A float resolves 1e6 and 1.0001e6 (a 1e7 far/near ratio) with room to spare.
    EXPECT_GT(ndcDepth(pi, -1.0e6f), ndcDepth(pi, -1.0001e6f));
}

TEST(CameraLens, OrthographicSpansTheFovHeightAtTheTargetAtEveryDepth) {
    Camera c;
    c.eye = {0, 0, 10}, c.target = {0, 0, 0}, c.fovYDeg = 60.0f;
    c.nearZ = 1.0f, c.farZ = 30.0f, c.projectionKind = Projection::Orthographic;
    c.depth = DepthMode::Standard;
    const float h = 10.0f * std::tan(glm::radians(30.0f));
    EXPECT_NEAR(c.orthoHalfHeight(), h, 1e-5f);
    const glm::mat4 p = c.projection(2.0f);
    for (float z : {-1.0f, -10.0f, -29.0f}) { // parallel rays: no shrinking with distance
        EXPECT_NEAR(ndcXY(p, {0.0f, h, z}).y, 1.0f, 1e-5f);
        EXPECT_NEAR(ndcXY(p, {2.0f * h, 0.0f, z}).x, 1.0f, 1e-5f);
    }
    EXPECT_NEAR(ndcDepth(p, -1.0f), -1.0f, 1e-5f);
    EXPECT_NEAR(ndcDepth(p, -30.0f), 1.0f, 1e-5f);
    c.depth = DepthMode::Reversed;
    const glm::mat4 pr = c.projection(2.0f);
    EXPECT_NEAR(ndcDepth(pr, -1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(ndcDepth(pr, -30.0f), 0.0f, 1e-6f);
}

TEST(CameraLens, ValidationFollowsTheDepthMode) {
    Camera c;
    EXPECT_EQ(c.depth, DepthMode::Reversed) << "the default is the robust mapping";
    c.nearZ = 1e-5f, c.farZ = 1e5f, c.depth = DepthMode::Standard; // a 1e10 ratio
    EXPECT_NE(errorOf([&] { validateCamera(c); }).find("or use reversed depth"), std::string::npos);
    c.depth = DepthMode::Reversed;
    EXPECT_NO_THROW(validateCamera(c));
    c.farZ = INFINITY;
    EXPECT_NO_THROW(validateCamera(c));
    c.projectionKind = Projection::Orthographic; // parallel rays never reach infinity's depth of 0
    EXPECT_NE(errorOf([&] { validateCamera(c); }).find("infinite far plane needs reversed depth and a perspective"),
              std::string::npos);
    c.projectionKind = Projection::Perspective, c.depth = DepthMode::Standard;
    EXPECT_NE(errorOf([&] { validateCamera(c); }).find("infinite far plane"), std::string::npos);
    c.farZ = -INFINITY, c.depth = DepthMode::Reversed;
    EXPECT_FALSE(errorOf([&] { validateCamera(c); }).empty());
}

TEST(CameraLens, CameraTextAcceptsAnInfiniteFarOnlyWithReversedDepth) {
    Camera base;
    base.depth = DepthMode::Standard;
    EXPECT_NE(errorOf([&] { parseCamera("0,0,5,0,0,0,0,1,0,60,0.01,inf", base); }).find("reversed depth"),
              std::string::npos);
    base.depth = DepthMode::Reversed;
    const Camera c = parseCamera("0,0,5,0,0,0,0,1,0,60,0.01,inf", base);
    EXPECT_TRUE(std::isinf(c.farZ));
    EXPECT_EQ(c.clip, ClipMode::Fixed);
    EXPECT_NE(errorOf([&] { parseCamera("0,0,5,inf,0,0", base); }).find("--camera: 'inf' is not a"),
              std::string::npos);
    EXPECT_EQ(parseProjection("orthographic"), Projection::Orthographic);
    EXPECT_NE(errorOf([] { parseProjection("fisheye"); }).find("expected perspective or orthographic"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parseDepthMode("log"); }).find("expected standard or reversed"), std::string::npos);
}

TEST(CameraLens, PresetsKeepProjectionDepthAndAnInfiniteFar) {
    Camera c;
    c.eye = {1, 2, 3}, c.projectionKind = Projection::Orthographic, c.depth = DepthMode::Reversed;
    c.nearZ = 0.5f, c.farZ = 50.0f, c.clip = ClipMode::Fixed;
    EXPECT_EQ(cameraFromJson(cameraToJson(c), "p.json"), c);
    c.projectionKind = Projection::Perspective, c.farZ = INFINITY;
    const nlohmann::json j = cameraToJson(c);
    EXPECT_EQ(j["far"], "inf");
    EXPECT_EQ(cameraFromJson(nlohmann::json::parse(j.dump()), "p.json"), c);

    nlohmann::json bad = j;
    bad["projection"] = "fisheye";
    EXPECT_NE(errorOf([&] { cameraFromJson(bad, "p.json"); }).find("p.json: camera.projection 'fisheye'"),
              std::string::npos);
    bad = j;
    bad["depth"] = 3;
    EXPECT_NE(errorOf([&] { cameraFromJson(bad, "p.json"); }).find("camera.depth must be a string"),
              std::string::npos);
    bad = j;
    bad["depth"] = "standard"; // an infinite far needs reversed depth
    EXPECT_NE(errorOf([&] { cameraFromJson(bad, "p.json"); }).find("p.json: camera: an infinite far plane"),
              std::string::npos);
}
