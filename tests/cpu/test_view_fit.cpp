// Fitting the view to real scenes: clip planes from the bounds, and the orbit target of a glTF
// camera on its view ray inside the scene (CornellBox, the millimetre engine).
#include "scene/camera.h"
#include "scene/load/load_scene.h"
#include "scene/view_fit.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ssao;

namespace {
std::string scenePath(const char* rel) {
    return std::string(SSAOLAB_SCENES_DIR) + "/" + rel;
}
} // namespace

TEST(ViewFit, ClipPlanesEncloseTheBoundsTightly) {
    Bounds b;
    b.add({-1, -1, -1});
    b.add({1, 1, 1});
    Camera c{{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60, 0.05f, 1e6f};
    const auto [n, f] = fitClipPlanes(c, b);
    EXPECT_LE(n, 9.0f);
    EXPECT_GT(n, 8.0f); // the box starts 9 units ahead
    EXPECT_GE(f, 11.0f);
    EXPECT_LT(f, 12.0f);
    const Camera e = effectiveCamera(c, b);
    EXPECT_EQ(e.nearZ, n);
    c.clip = ClipMode::Fixed; // the file's planes when asked for
    EXPECT_EQ(effectiveCamera(c, b).farZ, 1e6f);
    // Inside the box: near is a fixed fraction of far, never zero or negative.
    Camera inside{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 0.1f, 100};
    const auto [ni, fi] = fitClipPlanes(inside, b);
    EXPECT_GT(ni, 0.0f);
    EXPECT_NEAR(fi / ni, 1e4f, 1.0f);
}

TEST(ViewFit, GltfCamerasOrbitAroundTheSceneNotAUnitAhead) {
    for (const char* rel : {"CornellBox/cornellBox.gltf", "2CylinderEngine/2CylinderEngine.gltf",
                            "ShaderBall/shader_ball.gltf", "ReciprocatingSaw/ReciprocatingSaw.gltf"}) {
        const Scene s = loadScene(scenePath(rel));
        ASSERT_TRUE(s.camera.has_value()) << rel;
        const Camera& c = *s.camera;
        const float dist = glm::length(c.target - c.eye);
        const glm::vec3 fwd = (c.target - c.eye) / dist;
        // The target is on the view ray at the depth of the bounds' centre.
        EXPECT_NEAR(dist, glm::dot(s.bounds.center() - c.eye, fwd), 1e-3f * s.bounds.radius()) << rel;
        EXPECT_GT(dist, 0.1f * s.bounds.radius()) << rel; // was 1 unit: 1 mm on the engine
        // And it lies within the scene's bounding sphere.
        EXPECT_LT(glm::length(c.target - s.bounds.center()), s.bounds.radius()) << rel;
    }
}

TEST(ViewFit, EngineClipPlanesAreFittedNotTheFilesOneToAMillion) {
    const Scene s = loadScene(scenePath("2CylinderEngine/2CylinderEngine.gltf"));
    const Camera& file = *s.camera;
    EXPECT_GT(file.farZ / file.nearZ, 1e6f); // the file's planes: z-fighting territory
    EXPECT_EQ(file.clip, ClipMode::Fit);
    const Camera e = effectiveCamera(file, s.bounds);
    EXPECT_LT(e.farZ / e.nearZ, 10.0f); // the engine seen from outside: a tight depth range
    EXPECT_GT(e.nearZ, 100.0f);         // millimetres
}

TEST(ViewFit, FirstHitFindsTheNearestTriangle) {
    const Scene s = loadScene("builtin:plane");
    const auto hit = firstHit(s, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(*hit, 2.0f - s.bounds.max.y, 1e-4f);
    EXPECT_FALSE(firstHit(s, {0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}).has_value());
}

TEST(CameraValidation, ADepthRangeTheDepthBufferCannotResolveIsRefused) {
    // near 1e-9, far 1e9 passed validation and rendered an empty frame reported as AO 0/0/0
    // (with standard depth; reversed-Z float depth resolves it, tests/gl/test_lens.cpp).
    Camera base;
    base.depth = DepthMode::Standard;
    std::string msg;
    try {
        parseCamera("0,0,5,0,0,0,0,1,0,60,1e-9,1e9", base);
    } catch (const Error& e) {
        msg = e.what();
    }
    EXPECT_NE(msg.find("far/near = 1e+18 exceeds 1e+08"), std::string::npos) << msg;
    // 2CylinderEngine's own planes (0.05 .. 1e6) stay accepted.
    EXPECT_NO_THROW(parseCamera("0,0,5,0,0,0,0,1,0,60,0.05,1e6", base));
}
