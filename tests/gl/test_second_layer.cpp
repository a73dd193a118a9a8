// The second depth layer (gbuffer.second_layer, passes/second_layer_pass.h) and the bitmask that
// reads it: a wall the depth buffer hides behind a plate (builtin:hidden) is found again, against
// the corner's closed form; the layer never brightens the AO; a scene of nested parts (a part
// inside a part) is never worse against the reference with it; the inspector shows its taps.
#include "closed_form.h"
#include "scene/load/load_scene.h"
#include "gl_fixture.h"

#include "gl/readback.h"
#include "metrics/evaluate.h"
#include "passes/second_layer_pass.h"
#include "scene/scene.h"

#include <cmath>

using namespace ssao;
using namespace ssaotest;

namespace {
class SecondLayer : public GlTest {};

Settings bitmask(bool second) {
    Settings s = defaultSettings();
    s.ao.technique = "vbao";
    s.ao.radiusMode = RadiusMode::World;
    s.ao.radius = 1.0f;
    s.vbao.slices = 8;
    s.vbao.steps = 16;
    s.denoise.kind = DenoiseKind::None;
    s.gbuffer.secondLayer = second;
    return s;
}
} // namespace

TEST_F(SecondLayer, AWallTheDepthBufferHidesIsFoundBehindThePlate) {
    // builtin:hidden is builtin:corner with a plate between the eye and the wall, over 1.5 R from
    // every floor point measured: the floor's AO is still the wall's closed form.
    const CornerProfile open = cornerProfile(bitmask(false), "builtin:corner");
    const CornerProfile one = cornerProfile(bitmask(false), "builtin:hidden");
    const CornerProfile two = cornerProfile(bitmask(true), "builtin:hidden");
    std::printf("floor beside a wall, RMSE against the closed form: wall seen %.4f; wall hidden: one layer %.4f "
                "(at the wall %.3f), two layers %.4f (at the wall %.3f)\n",
                open.rmse, one.rmse, one.atWall, two.rmse, two.atWall);
    ASSERT_GT(one.bins, 20u);
    EXPECT_GT(one.rmse, 0.1);          // one layer sees only the plate, out of reach: the wall is lost
    EXPECT_GT(one.atWall, 0.9);
    EXPECT_LE(two.rmse, 0.02);          // two layers find it
    EXPECT_LE(std::abs(two.rmse - open.rmse), 0.01); // as well as when the wall is in sight
    EXPECT_LT(two.atWall, 0.6);
}

TEST_F(SecondLayer, GtaoFindsTheHiddenWallAsAHorizon) {
    auto gtao = [](bool second) {
        Settings s = bitmask(second);
        s.ao.technique = "gtao";
        s.gtao.quality = GtaoQuality::Ultra;
        return s;
    };
    const CornerProfile open = cornerProfile(gtao(false), "builtin:corner");
    const CornerProfile one = cornerProfile(gtao(false), "builtin:hidden");
    const CornerProfile two = cornerProfile(gtao(true), "builtin:hidden");
    std::printf("GTAO beside a wall, RMSE against the closed form: wall seen %.4f; wall hidden: one layer %.4f, "
                "two layers %.4f\n",
                open.rmse, one.rmse, two.rmse);
    EXPECT_GT(one.rmse, 0.1);
    EXPECT_LE(std::abs(two.rmse - open.rmse), 0.01);
    // Never brighter: the surface behind only ever raises a horizon.
    for (const char* name : {"builtin:showcase", "builtin:hidden"}) {
        const Rendered a = render(name, gtao(false), 160, 90), b = render(name, gtao(true), 160, 90);
        float brighter = 0;
        for (size_t i = 0; i < a.aoRaw.data.size(); ++i)
            brighter = std::max(brighter, b.aoRaw.data[i] - a.aoRaw.data[i]);
        EXPECT_LT(brighter, 1e-5f) << name;
    }
}

TEST_F(SecondLayer, HoldsTheSurfaceBehindAndNeverBrightensTheBitmask) {
    Settings s = bitmask(true);
    auto r = makeRenderer(loadScene("builtin:hidden"), s, 160, 120);
    r->render();
    const Image first = readBack(r->texture("gbuffer.position"), 4);
    const Image second = readBack(r->texture(SecondLayerPass::kOutput), 1);
    const glm::mat4 toWorld = glm::inverse(r->camera().view());
    long onPlate = 0, wallBehind = 0;
    for (size_t i = 0; i < first.data.size() / 4; ++i) {
        if (first.data[4 * i + 3] == 0.0f) continue;
        const glm::vec3 p1 = glm::vec3(toWorld * glm::vec4(first.data[4 * i], first.data[4 * i + 1], first.data[4 * i + 2], 1));
        if (std::abs(p1.z - 1.05f) > 1e-3f) continue; // a pixel on the plate's face
        ++onPlate;
        if (second.data[i] == 0.0f) continue;
        // The point on this pixel's ray at the layer's depth: its world z is the wall's face, z = -2.
        const glm::vec3 v1(first.data[4 * i], first.data[4 * i + 1], first.data[4 * i + 2]);
        const glm::vec3 p2 = glm::vec3(toWorld * glm::vec4(v1 * (1.0f / second.data[i] / -v1.z), 1)); // 1 / depth
        wallBehind += std::abs(p2.z + 2.0f) < 1e-3f;
    }
    ASSERT_GT(onPlate, 1000);
    EXPECT_GT(double(wallBehind), 0.95 * double(onPlate)) << wallBehind << " of " << onPlate;
    for (const char* name : {"builtin:showcase", "builtin:hidden", "builtin:slabs"}) {
        const Rendered a = render(name, bitmask(false), 160, 90), b = render(name, bitmask(true), 160, 90);
        float brighter = 0;
        for (size_t i = 0; i < a.aoRaw.data.size(); ++i)
            brighter = std::max(brighter, b.aoRaw.data[i] - a.aoRaw.data[i]);
        EXPECT_LT(brighter, 1e-5f) << name; // it only adds what hides sectors
        EXPECT_TRUE(finiteInRange(b.ao, 0.0f, 1.0f)) << name;
    }
}

TEST_F(SecondLayer, NestedPartsAreNeverWorseAgainstTheReference) {
    // 2CylinderEngine: parts inside parts, where a layer behind a thin shell is another part, not air.
    const Scene scene = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/2CylinderEngine/2CylinderEngine.gltf");
    EmbreeScene rt(scene);
    for (const bool backFaces : {false, true}) {
        double rmse[2] = {0, 0};
        for (const bool second : {false, true}) {
            Settings s = preset("vbao-high");
            s.gbuffer.secondLayer = second;
            s.gbuffer.backFaces = backFaces;
            auto r = makeRenderer(scene, s, 160, 90);
            r->render();
            const Evaluation e = judgeAgainstReference(*r, rt, 32);
            ASSERT_EQ(e.metrics.nonFinite, 0);
            rmse[second] = e.metrics.rmse;
        }
        std::printf("2CylinderEngine, back faces %s: RMSE one layer %.4f, two layers %.4f\n", backFaces ? "on" : "off",
                    rmse[0], rmse[1]);
        EXPECT_LE(rmse[1], rmse[0] + 0.002) << "back faces " << backFaces;
    }
}

TEST_F(SecondLayer, TheInspectorShowsWhichTapsTheSecondLayerClosed) {
    auto r = makeRenderer(loadScene("builtin:hidden"), bitmask(true), 160, 120);
    r->render();
    long second = 0, taps = 0;
    for (int y = 4; y < 120; y += 8)
        for (int x = 40; x < 120; x += 16)
            if (const auto pi = r->inspect(0, {x, y}))
                for (const InspectTap& t : pi->taps) second += t.secondLayer, ++taps;
    std::printf("%ld of %ld taps closed sectors through the second layer\n", second, taps);
    EXPECT_GT(second, 0);
    r->setSettings(bitmask(false)); // none without it
    r->render();
    for (int y = 4; y < 120; y += 8)
        for (int x = 40; x < 120; x += 16)
            if (const auto pi = r->inspect(0, {x, y}))
                for (const InspectTap& t : pi->taps) EXPECT_FALSE(t.secondLayer);
}

namespace {
// The second layer as rendered, 1 / linear depth per pixel (0 = none).
Image secondLayerOf(Renderer& r) {
    r.render();
    return readBack(r.texture(SecondLayerPass::kOutput), 1);
}

// Pixels where both layers hold the same surface (1/depth within 1e-5 relative) or neither has one.
double agreement(const Image& a, const Image& b) {
    long same = 0;
    for (size_t i = 0; i < a.data.size(); ++i)
        same += std::abs(a.data[i] - b.data[i]) <= 1e-5f * std::max(a.data[i], b.data[i]);
    return double(same) / double(a.data.size());
}
} // namespace

TEST_F(SecondLayer, TheSinglePassKeepsWhatThePeelKeepsOnAStillFrame) {
    // Mara et al.'s single pass against the previous frame's first layer: on a still camera the
    // previous frame is this one, and its layer is the peel's, pixel for pixel.
    for (const char* name : {"builtin:hidden", "builtin:slabs", "builtin:showcase"}) {
        const Scene scene = loadScene(name);
        Settings peel = bitmask(true), single = bitmask(true);
        single.gbuffer.secondLayerBuild = SecondLayerBuild::Previous;
        auto a = makeRenderer(scene, peel, 160, 120);
        auto b = makeRenderer(scene, single, 160, 120);
        const Image first = secondLayerOf(*a), once = secondLayerOf(*b); // the first frame: no previous one
        long held = 0;
        for (float v : first.data)
            held += v > 0.0f;
        b->invalidate(); // the second, run again: reprojects the first
        b->render();
        const Image again = readBack(b->texture(SecondLayerPass::kOutput), 1);
        std::printf("%s: %ld pixels hold a second layer; the single pass agrees on %.4f (first frame), %.4f (next)\n",
                    name, held, agreement(first, once), agreement(first, again));
        EXPECT_GT(held, 100) << name;
        EXPECT_GE(agreement(first, once), 0.999) << name;
        EXPECT_GE(agreement(first, again), 0.999) << name;
        EXPECT_EQ(b->graph().pass("second_layer"), nullptr) << name; // no second geometry pass
    }
}

TEST_F(SecondLayer, TheSinglePassReprojectsThePreviousFrameAsTheCameraMoves) {
    const Scene scene = loadScene("builtin:hidden");
    Settings peel = bitmask(true), single = bitmask(true);
    single.gbuffer.secondLayerBuild = SecondLayerBuild::Previous;
    auto a = makeRenderer(scene, peel, 160, 120);
    auto b = makeRenderer(scene, single, 160, 120);
    Camera cam = b->userCamera();
    b->render();
    const glm::vec3 offset = cam.eye - cam.target;
    const float step = glm::radians(1.0f); // an orbit of a degree per frame
    double worst = 1.0;
    for (int frame = 1; frame <= 4; ++frame) {
        const float c = std::cos(step * frame), s = std::sin(step * frame);
        Camera moved = cam;
        moved.eye = cam.target + glm::vec3(c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z);
        a->setCamera(moved), b->setCamera(moved);
        const Image exact = secondLayerOf(*a), reprojected = secondLayerOf(*b);
        worst = std::min(worst, agreement(exact, reprojected));
        EXPECT_TRUE(finiteInRange(reprojected, 0.0f, 1e6f));
    }
    std::printf("orbiting a degree a frame, the single pass agrees with the peel on at least %.4f of the pixels\n",
                worst);
    EXPECT_GE(worst, 0.97); // what the last frame did not see is what may differ
}

TEST_F(SecondLayer, TheSinglePassForgetsAFrameFromBeforeItWasTurnedOff) {
    // The layer on at one view, off while the camera moves far, on again: the frame it kept is not
    // this view's previous one, so it starts over as on a first frame.
    const Scene scene = loadScene("builtin:hidden");
    Settings peel = bitmask(true), single = bitmask(true), off = bitmask(false);
    single.gbuffer.secondLayerBuild = SecondLayerBuild::Previous;
    auto a = makeRenderer(scene, peel, 160, 120);
    auto b = makeRenderer(scene, single, 160, 120);
    b->render();
    Camera moved = b->userCamera();
    moved.eye = moved.target + glm::vec3(-1.0f, 0.6f, 1.0f) * glm::length(moved.eye - moved.target);
    b->setSettings(off);
    b->setCamera(moved);
    b->render();
    b->setSettings(single);
    a->setCamera(moved);
    EXPECT_GE(agreement(secondLayerOf(*a), secondLayerOf(*b)), 0.999);
}
