// Error in motion: the camera path (scene/camera_path.h), the reprojection of a pixel between two
// cameras (metrics/reprojection.h) and the instability and ghosting measures over float images
// (metrics/motion_metrics.h) and their bench summary, on inputs whose answers are known by construction.
#include "metrics/bench_summary.h"
#include "metrics/error_metrics.h"
#include "metrics/motion_metrics.h"
#include "metrics/reprojection.h"
#include "scene/camera_path.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace ssao;

namespace {

// Deterministic noise in [-0.5, 0.5) (LCG).
std::vector<float> noise(size_t n, unsigned seed) {
    std::vector<float> v(n);
    for (float& x : v) {
        seed = seed * 1664525u + 1013904223u;
        x = float(seed >> 8) / float(1u << 24) - 0.5f;
    }
    return v;
}

Camera lookingDownZ(glm::vec3 eye) {
    Camera c;
    c.eye = eye, c.target = eye + glm::vec3(0, 0, -1), c.fovYDeg = 60.0f, c.nearZ = 0.1f, c.farZ = 100.0f;
    return c;
}

// Linear view depth of a scene of a background plane at z = -5 and a square |x|, |y| <= 0.5 at
// z = -2 (world), seen by `c` (looking down -z) at w x h: ray-cast analytically.
std::vector<float> squareDepth(const Camera& c, int w, int h) {
    std::vector<float> d(size_t(w) * h);
    const float t = std::tan(glm::radians(c.fovYDeg) * 0.5f), aspect = float(w) / float(h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float nx = 2.0f * (x + 0.5f) / w - 1.0f, ny = 1.0f - 2.0f * (y + 0.5f) / h;
            const float z = c.eye.z + 2.0f; // view depth of the square's plane
            const float px = c.eye.x + nx * t * aspect * z, py = c.eye.y + ny * t * z;
            d[size_t(y) * w + x] = std::abs(px) <= 0.5f && std::abs(py) <= 0.5f ? z : c.eye.z + 5.0f;
        }
    return d;
}

MotionFrameInput frame(const std::vector<float>& test, const std::vector<float>& ref, const std::vector<int>* prev) {
    MotionFrameInput f;
    f.test = test.data(), f.reference = ref.data();
    f.toPrevious = prev ? prev->data() : nullptr;
    return f;
}

std::vector<int> identity(size_t n) {
    std::vector<int> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = int(i);
    return v;
}

} // namespace

TEST(CameraPath, OrbitsAndDolliesTowardTheTargetInEvenSteps) {
    Camera start = lookingDownZ({0, 0, 10});
    start.target = {0, 0, 0};
    const std::vector<Camera> path = cameraPath(start, {9, 8.0f, 0.2f});
    ASSERT_EQ(path.size(), 9u);
    EXPECT_EQ(path[0], start);
    for (size_t k = 0; k < path.size(); ++k) {
        const float t = float(k) / 8.0f;
        EXPECT_EQ(path[k].target, start.target);
        EXPECT_NEAR(glm::length(path[k].eye - path[k].target), 10.0f * (1.0f - 0.2f * t), 1e-4f) << k;
        // The turn about the up axis (+y): the angle from +z toward +x.
        EXPECT_NEAR(glm::degrees(std::atan2(path[k].eye.x, path[k].eye.z)), 8.0f * t, 1e-3f) << k;
        EXPECT_NEAR(path[k].eye.y, 0.0f, 1e-5f);
    }
    EXPECT_EQ(cameraPath(start, {9, 8.0f, 0.2f}), path); // deterministic
    start.eye = {0.3f, 1.7f, 9.1f}; // a still path is the start, bit for bit (no round trip through the target)
    for (const Camera& c : cameraPath(start, {4, 0.0f, 0.0f})) EXPECT_EQ(c, start);
    EXPECT_THROW(cameraPath(start, {1, 8.0f, 0.2f}), Error);
    EXPECT_THROW(cameraPath(start, {8, 180.0f, 0.2f}), Error);
    EXPECT_THROW(cameraPath(start, {8, 4.0f, 1.0f}), Error);
    EXPECT_THROW(cameraPath(start, {8, NAN, 0.2f}), Error);
}

TEST(Reprojection, AStillCameraFollowsEveryPixelToItselfAndSkyToNothing) {
    const int w = 32, h = 18;
    const Camera c = lookingDownZ({0, 0, 0});
    std::vector<float> depth = squareDepth(c, w, h), geometry(depth.size(), 1.0f);
    geometry[5] = 0.0f; // one sky pixel
    const DepthFrame f{&c, depth.data(), geometry.data()};
    const std::vector<int> map = reprojectToPrevious(f, f, w, h);
    for (size_t i = 0; i < map.size(); ++i)
        EXPECT_EQ(map[i], i == 5 ? kDisoccluded : int(i)) << i;
}

TEST(Reprojection, ASidewaysMoveShiftsAFacingPlaneByItsParallax) {
    const int w = 64, h = 36;
    Camera a = lookingDownZ({0, 0, 0}), b = lookingDownZ({0.25f, 0, 0});
    a.fovYDeg = b.fovYDeg = 50.0f;
    const std::vector<float> depth(size_t(w) * h, 5.0f); // a plane facing the camera 5 units away
    // Moving right by 0.25 moves the image left by 0.25 / (5 tan(fov/2) aspect) x w/2 pixels.
    const float shift = 0.25f / (5.0f * std::tan(glm::radians(25.0f)) * (64.0f / 36.0f)) * 32.0f;
    float px = 0, py = 0, pz = 0;
    ASSERT_TRUE(reprojectPoint(b, a, w, h, 10, 7, 5.0f, px, py, pz));
    EXPECT_NEAR(px, 10.5f + shift, 1e-3f);
    EXPECT_NEAR(py, 7.5f, 1e-3f);
    EXPECT_NEAR(pz, 5.0f, 1e-4f);
    const std::vector<int> map = reprojectToPrevious({&b, depth.data(), nullptr}, {&a, depth.data(), nullptr}, w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float from = x + 0.5f + shift; // where the point was
            const int i = y * w + x;
            if (from > float(w)) {
                EXPECT_EQ(map[i], kOffScreen) << x << "," << y;
                continue;
            }
            ASSERT_GE(map[i], 0) << x << "," << y;
            EXPECT_LE(std::abs(float(map[i] % w) + 0.5f - from), 0.5f + 1e-3f) << x << "," << y;
            EXPECT_EQ(map[i] / w, y);
        }
}

TEST(Reprojection, AnOrthographicViewShiftsByTheMoveOverItsHalfWidth) {
    const int w = 64, h = 36;
    Camera a = lookingDownZ({0, 0, 0});
    a.target = {0, 0, -4}, a.projectionKind = Projection::Orthographic; // spans 4 tan(30 deg) up and down
    Camera b = a;
    b.eye.x += 0.1f, b.target.x += 0.1f;
    const float shift = 0.1f / (4.0f * std::tan(glm::radians(30.0f)) * (64.0f / 36.0f)) * 32.0f;
    float px = 0, py = 0, pz = 0;
    ASSERT_TRUE(reprojectPoint(b, a, w, h, 20, 9, 7.0f, px, py, pz)); // any depth: parallel rays
    EXPECT_NEAR(px, 20.5f + shift, 1e-3f);
    EXPECT_NEAR(py, 9.5f, 1e-3f);
    EXPECT_NEAR(pz, 7.0f, 1e-4f);
}

TEST(Reprojection, FindsTheBackgroundASquareUncoversWhenTheCameraMoves) {
    const int w = 96, h = 54;
    const Camera a = lookingDownZ({0, 0, 0}), b = lookingDownZ({0.5f, 0, 0});
    const std::vector<float> da = squareDepth(a, w, h), db = squareDepth(b, w, h);
    const std::vector<int> map = reprojectToPrevious({&b, db.data(), nullptr}, {&a, da.data(), nullptr}, w, h);
    // Truth: a background pixel of b is disoccluded when the line from a's eye to its point crosses
    // the square; off screen when a did not see the point.
    const float t = std::tan(glm::radians(30.0f)), aspect = float(w) / float(h);
    int wrong = 0, disoccluded = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int i = y * w + x;
            const float nx = 2.0f * (x + 0.5f) / w - 1.0f, ny = 1.0f - 2.0f * (y + 0.5f) / h;
            const float z = db[size_t(i)];
            const glm::vec3 p(b.eye.x + nx * t * aspect * z, ny * t * z, -z);
            int expected = 0; // visible in a
            if (std::abs(p.x / (-p.z) / (t * aspect)) > 1.0f) expected = kOffScreen;
            else if (z > 4.0f && std::abs(p.x * 0.4f) <= 0.5f && std::abs(p.y * 0.4f) <= 0.5f) expected = kDisoccluded;
            disoccluded += expected == kDisoccluded;
            const int got = map[size_t(i)] >= 0 ? 0 : map[size_t(i)];
            wrong += got != expected;
        }
    // The strip the square uncovers: x in [0.5, 1.25] on the background, 7 px x 23 px.
    EXPECT_GT(disoccluded, 100);
    // Only pixels on the strip's border may go either way (the 2x2 search finds the background there).
    EXPECT_LE(wrong, 2 * h) << disoccluded;
}

TEST(Reprojection, AFloorSeenAtAGrazingAngleStaysVisibleWhenTheCameraMovesForward) {
    // The floor y = -1 under a camera looking slightly down, at a low resolution: far away, its
    // depth changes by more than the 2 % tolerance from one pixel to the next, so the nearest
    // pixel's depth alone would call much of it disoccluded.
    const int w = 64, h = 36;
    Camera a;
    a.eye = {0, 0, 0}, a.target = {0, -0.25f, -1}, a.fovYDeg = 50.0f;
    Camera b = a;
    b.eye.z -= 0.2f, b.target.z -= 0.2f;
    auto floorDepth = [&](const Camera& c, std::vector<float>& geometry) {
        std::vector<float> d(size_t(w) * h, 0.0f);
        geometry.assign(d.size(), 0.0f);
        const glm::vec3 fwd = glm::normalize(c.target - c.eye), right = glm::normalize(glm::cross(fwd, c.up));
        const glm::vec3 up = glm::cross(right, fwd);
        const float t = std::tan(glm::radians(c.fovYDeg) * 0.5f), aspect = float(w) / float(h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float nx = 2.0f * (x + 0.5f) / w - 1.0f, ny = 1.0f - 2.0f * (y + 0.5f) / h;
                const float dy = (fwd + right * (nx * t * aspect) + up * (ny * t)).y; // per unit of view depth
                const float z = dy < 0.0f ? (-1.0f - c.eye.y) / dy : 0.0f;
                if (z > 0.0f && z < 40.0f) d[size_t(y) * w + x] = z, geometry[size_t(y) * w + x] = 1.0f;
            }
        return d;
    };
    std::vector<float> ga, gb;
    const std::vector<float> da = floorDepth(a, ga), db = floorDepth(b, gb);
    const std::vector<int> map = reprojectToPrevious({&b, db.data(), gb.data()}, {&a, da.data(), ga.data()}, w, h);
    int floor = 0, lost = 0;
    for (size_t i = 0; i < map.size(); ++i) {
        if (!(gb[i] > 0.0f)) continue;
        ++floor;
        lost += map[i] == kDisoccluded;
    }
    ASSERT_GT(floor, 500);
    EXPECT_LE(lost, w) << "of " << floor; // at most the far edge, where the floor meets the cut-off
}

TEST(MotionMetrics, AStillSceneUnderAStillCameraHasNoInstabilityAndNoDisocclusion) {
    const int w = 40, h = 30;
    const size_t n = size_t(w) * h;
    std::vector<float> ref(n), test(n);
    const std::vector<float> grain = noise(n, 7);
    for (size_t i = 0; i < n; ++i) ref[i] = 0.5f + 0.4f * grain[i], test[i] = ref[i] + 0.1f * grain[(i * 7) % n];
    const std::vector<int> id = identity(n);
    const MotionMetrics m = computeMotionMetrics(w, h, {frame(test, ref, nullptr), frame(test, ref, &id), frame(test, ref, &id)});
    EXPECT_EQ(m.frames, 3);
    EXPECT_EQ(m.instability, 0.0);
    EXPECT_EQ(m.pairs, long(2 * n));
    EXPECT_EQ(m.disoccludedPixels, 0);
    EXPECT_TRUE(std::isnan(m.ghosting));
    MetricsInput in;
    in.width = w, in.height = h, in.test = test.data(), in.reference = ref.data();
    const double rmse = computeErrorMetrics(in).rmse;
    EXPECT_DOUBLE_EQ(m.rmseMean, rmse);
    EXPECT_DOUBLE_EQ(m.rmseMax, rmse);
    EXPECT_NEAR(m.mseMean, rmse * rmse, 1e-15);
    EXPECT_NEAR(motionObjective(m), rmse * rmse, 1e-15);
}

TEST(MotionMetrics, GrainThatChangesEveryFrameIsItsRmsChangeAndRealChangeCancels) {
    const int w = 64, h = 36;
    const size_t n = size_t(w) * h;
    const std::vector<int> id = identity(n);
    std::vector<std::vector<float>> tests, refs;
    for (unsigned k = 0; k < 4; ++k) {
        const std::vector<float> g = noise(n, 100 + k);
        tests.emplace_back(n), refs.emplace_back(n, 0.6f);
        for (size_t i = 0; i < n; ++i) tests.back()[i] = 0.6f + 0.2f * g[i];
    }
    std::vector<MotionFrameInput> frames;
    double d2 = 0;
    for (size_t k = 0; k < 4; ++k) {
        frames.push_back(frame(tests[k], refs[k], k ? &id : nullptr));
        for (size_t i = 0; k && i < n; ++i) d2 += std::pow(double(tests[k][i]) - tests[k - 1][i], 2.0);
    }
    const MotionMetrics m = computeMotionMetrics(w, h, frames);
    EXPECT_NEAR(m.instability, std::sqrt(d2 / double(3 * n)), 1e-9);
    // Independent uniform grain of width 0.2 per frame: the change's RMS is sqrt(2) x 0.2/sqrt(12).
    EXPECT_NEAR(m.instability, std::sqrt(2.0) * 0.2 / std::sqrt(12.0), 0.005);

    // The AO really changes (the reference with it) and the technique follows with a steady error:
    // no instability.
    for (size_t k = 0; k < 4; ++k)
        for (size_t i = 0; i < n; ++i) refs[k][i] = 0.3f + 0.1f * float(k) + 0.05f * float(i % 5), tests[k][i] = refs[k][i] + 0.07f;
    EXPECT_NEAR(computeMotionMetrics(w, h, frames).instability, 0.0, 1e-6);
    // The reference's own noise floor: its standard errors in quadrature.
    const std::vector<float> se(n, 0.1f);
    for (auto& f : frames) f.referenceStdErr = se.data();
    EXPECT_NEAR(computeMotionMetrics(w, h, frames).instabilityFloor, std::sqrt(0.02), 1e-6);
}

TEST(MotionMetrics, ADisocclusionsFirstFramesAreJudgedAgainstStablePixels) {
    const int w = 20, h = 10;
    const size_t n = size_t(w) * h;
    std::vector<float> ref(n, 0.5f);
    std::vector<std::vector<float>> tests(4, std::vector<float>(n, 0.55f)); // stable error 0.05
    std::vector<std::vector<int>> maps(4, identity(n));
    // Frame 1: pixels 0..19 (the top row) appear from behind a surface, pixels 20..29 enter at the
    // frame's edge. The fresh ones carry a ghost of 0.3 in their first two frames, then settle; the
    // edge ones are wrong by 0.9 but are no disocclusion.
    for (int i = 0; i < 20; ++i) maps[1][size_t(i)] = kDisoccluded;
    for (int i = 20; i < 30; ++i) maps[1][size_t(i)] = kOffScreen;
    for (int i = 0; i < 20; ++i) tests[1][size_t(i)] = tests[2][size_t(i)] = 0.8f;
    for (int i = 20; i < 30; ++i) tests[1][size_t(i)] = tests[2][size_t(i)] = 1.4f;
    std::vector<MotionFrameInput> frames;
    for (size_t k = 0; k < 4; ++k) frames.push_back(frame(tests[k], ref, k ? &maps[k] : nullptr));
    const MotionMetrics m = computeMotionMetrics(w, h, frames, {2, 40}); // 40 fresh pixels back a figure here
    EXPECT_EQ(m.disoccludedPixels, 40); // 20 pixels x their first 2 frames
    EXPECT_NEAR(m.disoccludedMae, 0.3, 1e-6);
    EXPECT_NEAR(m.stableMae, 0.05, 1e-6);
    EXPECT_NEAR(m.ghosting, 0.25, 1e-6);
    // Stable: every pixel of frames 1..3 but the 30 young ones of frames 1 and 2.
    EXPECT_EQ(m.stablePixels, long(3 * n - 60));
    // Followed pairs: the young pixels of frame 1 have no previous pixel.
    EXPECT_EQ(m.pairs, long(3 * n - 30));
    // One frame of freshness: only frame 1's disoccluded pixels.
    EXPECT_EQ(computeMotionMetrics(w, h, frames, {1}).disoccludedPixels, 20);
}

TEST(MotionMetrics, GhostingFromTooFewDisoccludedPixelsIsNoFigure) {
    // Two disoccluded pixels once printed as a ghosting of +0.6073: a mean over 2 pixels says nothing.
    const int w = 20, h = 10;
    const size_t n = size_t(w) * h;
    std::vector<float> ref(n, 0.5f);
    std::vector<std::vector<float>> tests(3, std::vector<float>(n, 0.55f));
    std::vector<std::vector<int>> maps(3, identity(n));
    maps[1][0] = kDisoccluded;
    tests[1][0] = tests[2][0] = 1.0f;
    std::vector<MotionFrameInput> frames;
    for (size_t k = 0; k < 3; ++k) frames.push_back(frame(tests[k], ref, k ? &maps[k] : nullptr));
    const MotionMetrics m = computeMotionMetrics(w, h, frames);
    EXPECT_EQ(m.disoccludedPixels, 2);
    EXPECT_TRUE(std::isnan(m.ghosting));
    EXPECT_EQ(ghostingText(m), "n/a (2 pixels)");
    EXPECT_EQ(ghostingText(computeMotionMetrics(w, h, frames, {2, 2})), "+0.4500"); // 0.5 fresh - 0.05 stable
}

TEST(MotionMetrics, NonFiniteAoCountsAsOpenAndAmbiguousPixelsAreLeftOut) {
    const int w = 4, h = 1;
    const std::vector<int> id = identity(4);
    const std::vector<float> ref(4, 0.5f), a = {0.5f, 0.5f, 0.5f, 0.5f}, b = {NAN, 0.5f, 0.5f, 0.9f};
    const std::vector<float> exclude = {0, 0, 0, 1};
    std::vector<MotionFrameInput> f = {frame(a, ref, nullptr), frame(b, ref, &id)};
    for (auto& x : f) x.exclude = exclude.data();
    const MotionMetrics m = computeMotionMetrics(w, h, f);
    EXPECT_EQ(m.pairs, 3);
    EXPECT_NEAR(m.instability, std::sqrt(0.25 / 3.0), 1e-6); // the NaN as 1: a change of 0.5
    EXPECT_THROW(computeMotionMetrics(w, h, {MotionFrameInput{}}), std::invalid_argument);
}

TEST(MotionMetrics, ABenchConfigurationSummarisesItsViewsInMotion) {
    std::vector<ViewResult> views(3);
    for (size_t i = 0; i < 3; ++i) views[i].config = 0, views[i].viewpoint = "v" + std::to_string(i);
    views[0].hasMotion = views[1].hasMotion = true;
    views[0].motion = {0.3, 0.5, 0.1, NAN};
    views[1].motion = {0.4, 0.45, 0.2, 0.05};
    const ConfigSummary s = summarize(views, 1, 0)[0];
    EXPECT_NEAR(s.motion.rmseMean, std::sqrt((0.09 + 0.16) / 2), 1e-12); // RMS over the views measured in motion
    EXPECT_EQ(s.motion.rmseMax, 0.5);
    EXPECT_NEAR(s.motion.instability, std::sqrt((0.01 + 0.04) / 2), 1e-12);
    EXPECT_NEAR(s.motion.ghosting, 0.05, 1e-12); // over the views that had a disocclusion
    views[0].hasMotion = views[1].hasMotion = false;
    EXPECT_TRUE(std::isnan(summarize(views, 1, 0)[0].motion.rmseMean));
}
