// The screen-space oracle (reference_ao.h, visibility = Screen): the ground truth's integral, R
// and rays with visibility decided by the G-buffer's depth layers alone. Where the screen holds
// every occluder it equals the truth; where an occluder is hidden it provably misses it.
#include "reference/reference_ao.h"
#include "reference/screen_layers.h"
#include "reference_scenes.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace ssao;
using namespace ssaotest;

namespace {
ReferenceSettings oracle(float R, int rays, int layers = 1, float thickness = INFINITY) {
    ReferenceSettings s{R, rays};
    s.visibility = ReferenceVisibility::Screen;
    s.layers = layers;
    s.thickness = thickness;
    return s;
}
} // namespace

TEST(ScreenOracle, AnOpenPlaneIsUnoccluded) {
    const Scene s = floorScene(false);
    EmbreeScene rt(s);
    const ReferenceImage img = traceReference(rt, lookDown({3, 0, -2}, 5.0f), 48, 32, oracle(1.0f, 64));
    for (size_t i = 0; i < img.ao.size(); ++i)
        ASSERT_EQ(img.ao[i], 1.0f) << i; // no self-occlusion from the pixel grid
}

TEST(ScreenOracle, EqualsTheTruthWhereTheScreenHoldsTheOccluder) {
    // The floor beside a wall, seen from the open side and above: the wall's face is on screen, so
    // every ray that the truth finds blocked runs behind a visible surface.
    const Scene s = floorScene(true);
    EmbreeScene rt(s);
    const float R = 0.5f;
    Camera cam;
    cam.eye = {2.2f, 1.6f, 0.0f};
    cam.target = {0.35f, 0.1f, 0.0f};
    cam.fovYDeg = 50.0f;
    cam.nearZ = 0.01f;
    cam.farZ = 100.0f;
    cam.clip = ClipMode::Fixed;
    const int w = 96, h = 64;
    const ReferenceImage truth = traceReference(rt, cam, w, h, {R, 512});
    const ReferenceImage screen = traceReference(rt, cam, w, h, oracle(R, 512));
    double se = 0, seTruth = 0;
    long n = 0;
    for (size_t i = 0; i < truth.ao.size(); ++i) {
        if (truth.geometry[i] == 0.0f) continue;
        // Floor pixels whose R-neighbourhood lies in view (the middle of the frame).
        const int x = int(i % w), y = int(i / w);
        if (x < w / 6 || x > w - w / 6 || y < h / 4 || y > h - h / 6) continue;
        se += (screen.ao[i] - truth.ao[i]) * (screen.ao[i] - truth.ao[i]);
        seTruth += (1.0 - truth.ao[i]) * (1.0 - truth.ao[i]);
        ++n;
    }
    ASSERT_GT(n, 500);
    const double rmse = std::sqrt(se / n), occlusion = std::sqrt(seTruth / n);
    std::printf("oracle vs truth, occluder on screen: RMSE %.4f (the truth's own occlusion RMS %.3f)\n", rmse,
                occlusion);
    EXPECT_GT(occlusion, 0.1) << "the view must hold real occlusion";
    EXPECT_LT(rmse, 0.02);
}

TEST(ScreenOracle, MissesAnOccluderTheScreenDoesNotHold) {
    // The wall x = 0 stands just outside the left edge of the frame (the view covers x from about
    // 0.32 to 1.28 on the floor): no pixel, of either layer, holds it. The truth darkens the floor
    // within R of it by the closed form; the oracle cannot, and reads exactly 1.
    const Scene s = floorScene(true);
    EmbreeScene rt(s);
    const float R = 1.0f;
    const Camera cam = lookDown({0.8f, 0, 0}, 1.0f, 40.0f);
    const int w = 64, h = 48;
    const ReferenceImage truth = traceReference(rt, cam, w, h, {R, 256});
    for (int layers : {1, 2}) {
        const ReferenceImage screen = traceReference(rt, cam, w, h, oracle(R, 256, layers));
        long near = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * w + x;
                ASSERT_EQ(truth.geometry[i], 1.0f);
                const glm::vec3 p = hitPosition(cam, w, h, x, y, truth.depth[i]);
                ASSERT_NEAR(p.y, 0.0f, 1e-3f) << "only the floor is in view";
                if (p.x > 0.6f) continue;
                EXPECT_EQ(screen.ao[i], 1.0f) << "layers " << layers << " x " << p.x;
                EXPECT_NEAR(truth.ao[i], wallClosedForm(p.x, R), 0.06) << p.x;
                ++near;
            }
        EXPECT_GT(near, 200);
    }
}

TEST(ScreenOracle, AThinnerSurfaceLetsRaysPassBehindIt) {
    // A box's top seen from above with the floor beside it: with a thickness of 0.05 R the box is a
    // shell a ray can pass behind, so the floor beside it is brighter than under the height field.
    Scene s = floorScene(false);
    quad(s, {-0.5f, 0.6f, -0.5f}, {-0.5f, 0.6f, 0.5f}, {0.5f, 0.6f, 0.5f}, {0.5f, 0.6f, -0.5f}); // a floating lid
    s.draws.back().indexCount = uint32_t(s.indices.size());
    s.computeBounds();
    EmbreeScene rt(s);
    const Camera cam = lookDown({0.0f, 0, 0}, 4.0f, 50.0f);
    const ReferenceImage thick = traceReference(rt, cam, 64, 48, oracle(1.0f, 128, 1, INFINITY));
    const ReferenceImage thin = traceReference(rt, cam, 64, 48, oracle(1.0f, 128, 1, 0.05f));
    double a = 0, b = 0;
    for (size_t i = 0; i < thick.ao.size(); ++i)
        a += thick.ao[i], b += thin.ao[i];
    EXPECT_GT(b, a + 1.0) << "a thin lid occludes fewer rays than a solid block";
}

TEST(ScreenOracle, ABackFaceLayerGivesTheTrueThicknessAndStepsOverNoThinSolid) {
    // Thin closed boxes (0.1 R thick) standing on the floor, seen obliquely. With one layer of 1 R
    // the oracle makes each box 10 times too deep (rays that pass behind it are blocked); with the
    // back face as the second layer the solid ends where it really does, so the oracle moves toward
    // the truth; and every ray through a box is still blocked (a box no step can jump over).
    Scene s = floorScene(false);
    for (float x : {-1.0f, 0.0f, 1.0f})
        box(s, {x - 0.05f, 0.0f, -1.5f}, {x + 0.05f, 0.8f, 1.5f});
    s.draws.back().indexCount = uint32_t(s.indices.size());
    s.computeBounds();
    EmbreeScene rt(s);
    Camera cam = lookDown({0, 0, 0}, 3.0f, 50.0f);
    cam.eye = {0.0f, 2.5f, 2.5f};
    cam.up = {0, 1, 0};
    const int w = 64, h = 48;
    const float R = 1.0f;
    const ReferenceImage truth = traceReference(rt, cam, w, h, {R, 256});
    const ReferenceImage one = traceReference(rt, cam, w, h, oracle(R, 256, 1, 1.0f));
    const ReferenceImage two = traceReference(rt, cam, w, h, oracle(R, 256, 2, 1.0f));
    double se1 = 0, se2 = 0, b1 = 0, b2 = 0;
    long n = 0;
    for (size_t i = 0; i < truth.ao.size(); ++i) {
        if (!(truth.geometry[i] > 0.0f)) continue;
        se1 += (one.ao[i] - truth.ao[i]) * (one.ao[i] - truth.ao[i]);
        se2 += (two.ao[i] - truth.ao[i]) * (two.ao[i] - truth.ao[i]);
        b1 += one.ao[i] - truth.ao[i], b2 += two.ao[i] - truth.ao[i];
        ++n;
    }
    ASSERT_GT(n, 1000);
    const double r1 = std::sqrt(se1 / n), r2 = std::sqrt(se2 / n);
    std::printf("1 layer of 1 R: RMSE %.4f bias %+.4f; back-face layer: RMSE %.4f bias %+.4f\n", r1, b1 / n, r2, b2 / n);
    EXPECT_LT(r2, 0.7 * r1);
    EXPECT_LT(b1 / n, -0.005) << "one thick layer over-occludes";
    EXPECT_GT(b2 / n, b1 / n) << "the true thickness removes the over-occlusion";
    EXPECT_LT(std::abs(b2 / n), 0.012) << "what is left is what neither layer holds, not rays stepping through a box";
}

TEST(ScreenOracle, BadSettingsAreRefused) {
    const Scene s = floorScene(false);
    EmbreeScene rt(s);
    const Camera cam = lookDown({0, 0, 0}, 2.0f);
    ReferenceSettings bad = oracle(1.0f, 4, 3);
    EXPECT_THROW(traceReference(rt, cam, 8, 8, bad), Error);
    bad = oracle(1.0f, 4, 1, 0.0f);
    EXPECT_THROW(traceReference(rt, cam, 8, 8, bad), Error);
    bad = oracle(1.0f, 4);
    bad.variant = ReferenceVariant::Obscurance;
    EXPECT_THROW(traceReference(rt, cam, 8, 8, bad), Error);
}

TEST(ScreenOracle, AGuardBandHoldsTheOccluderJustOffScreen) {
    // The wall just outside the frame (as above): a guard band holds its foot (32 px: up to about
    // 0.18 R high; 128 px: about 0.67 R), so the truth's darkening near the edge comes back, more
    // of it the wider the band.
    const Scene s = floorScene(true);
    EmbreeScene rt(s);
    const float R = 1.0f;
    const Camera cam = lookDown({0.8f, 0, 0}, 1.0f, 40.0f);
    const int w = 64, h = 48;
    const ReferenceImage truth = traceReference(rt, cam, w, h, {R, 256});
    std::vector<double> rmse;
    for (int g : {0, 32, 128}) {
        ReferenceSettings band = oracle(R, 256);
        band.guardBand = g;
        const ReferenceImage img = traceReference(rt, cam, w, h, band);
        double se = 0;
        for (size_t i = 0; i < truth.ao.size(); ++i)
            se += (img.ao[i] - truth.ao[i]) * (img.ao[i] - truth.ao[i]);
        rmse.push_back(std::sqrt(se / double(truth.ao.size())));
        std::printf("oracle vs truth near an off-screen wall, guard band %3d px: RMSE %.4f\n", g, rmse.back());
    }
    EXPECT_GT(rmse[0], 0.05);
    EXPECT_LT(rmse[1], rmse[0]);
    EXPECT_LT(rmse[2], 0.5 * rmse[0]);
}
