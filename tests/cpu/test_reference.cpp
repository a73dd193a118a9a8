// The ray-traced reference against closed forms (XeGTAO's definition: cosine-weighted binary
// visibility within R), its determinism across threads and batches, and its disk cache.
#include "base/image.h"
#include "scene/load/load_scene.h"
#include "metrics/error_metrics.h"
#include "reference/reference_cache.h"
#include "reference/sampling.h"
#include "reference_scenes.h"
#include "scene/load/builtin_scenes.h"
#include "scene/scene.h"
#include "test_util.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace ssao;

using namespace ssaotest;

TEST(Reference, SobolPointsAreStratifiedAndSeedDependent) {
    // The first 2^k points of a (0,2)-sequence put exactly one point in each 1/2^k column and row.
    std::vector<int> col(16, 0), row(16, 0);
    for (uint32_t i = 0; i < 16; ++i) {
        const auto s = sampling::sobol2D(i, 12345u);
        ASSERT_GE(s.u, 0.0f);
        ASSERT_LT(s.u, 1.0f);
        ++col[int(s.u * 16)];
        ++row[int(s.v * 16)];
    }
    for (int k = 0; k < 16; ++k) {
        EXPECT_EQ(col[k], 1) << k;
        EXPECT_EQ(row[k], 1) << k;
    }
    EXPECT_NE(sampling::sobol2D(3, 1).u, sampling::sobol2D(3, 2).u);
    // Cosine-weighted directions: E[cos] = 2/3 for pdf cos/pi.
    double sum = 0;
    for (uint32_t i = 0; i < 4096; ++i) {
        float x, y, z;
        sampling::cosineHemisphere(sampling::sobol2D(i, 7u), x, y, z);
        ASSERT_NEAR(x * x + y * y + z * z, 1.0f, 1e-5f);
        sum += z;
    }
    EXPECT_NEAR(sum / 4096, 2.0 / 3.0, 1e-3);
}

TEST(Reference, OpenPlaneIsUnoccluded) {
    const Scene s = floorScene(false);
    EmbreeScene rt(s);
    const Camera cam = lookDown({3, 0, -2}, 5.0f);
    const ReferenceImage img = traceReference(rt, cam, 48, 32, {1.0f, 256});
    long geo = 0;
    for (size_t i = 0; i < img.ao.size(); ++i) {
        ASSERT_EQ(img.geometry[i], 1.0f); // the floor fills the view
        EXPECT_EQ(img.ao[i], 1.0f) << i;
        EXPECT_EQ(img.stdErr[i], 0.0f);
        ++geo;
    }
    EXPECT_EQ(geo, 48 * 32);
    EXPECT_EQ(img.aoRays, 48L * 32 * 256);
    // The primary hit's view depth is the camera height on a plane facing the camera.
    EXPECT_NEAR(img.depth[16 * 48 + 24], 5.0f, 1e-4f);
}

TEST(Reference, FloorBesideAWallMatchesTheClosedForm) {
    const Scene s = floorScene(true);
    EmbreeScene rt(s);
    const float R = 1.0f;
    const Camera cam = lookDown({0.6f, 0, 0}, 2.0f, 40.0f); // x in ~[-0.13, 1.33] at the floor
    const int w = 64, h = 48;
    for (auto variant : {ReferenceVariant::Visibility, ReferenceVariant::Obscurance}) {
        const ReferenceImage img = traceReference(rt, cam, w, h, {R, 1024, variant});
        double se = 0;
        long n = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * w + x;
                ASSERT_EQ(img.geometry[i], 1.0f);
                const glm::vec3 p = hitPosition(cam, w, h, x, y, img.depth[i]);
                if (std::abs(p.y) > 1e-3f || p.x < 1e-3f) continue; // the wall or behind it
                const double ao = img.ao[i];
                ASSERT_TRUE(std::isfinite(ao));
                if (variant == ReferenceVariant::Visibility) {
                    se += (ao - wallClosedForm(p.x, R)) * (ao - wallClosedForm(p.x, R));
                } else {
                    // Falloff only forgives occluders: never darker than binary visibility.
                    EXPECT_GE(ao + 0.03, wallClosedForm(p.x, R)) << p.x;
                }
                ++n;
            }
        ASSERT_GT(n, w * h / 2);
        if (variant == ReferenceVariant::Visibility) {
            const double rmse = std::sqrt(se / n);
            EXPECT_LT(rmse, 0.01) << "floor pixels " << n;
            std::printf("floor beside a wall: RMSE %.5f over %ld pixels (1024 rays)\n", rmse, n);
        }
    }
}

TEST(Reference, InsideAClosedBoxSmallerThanRIsFullyOccluded) {
    Scene s;
    const float a = 0.5f; // box [-a, a]^3, diagonal 1.73 < R = 2
    const glm::vec3 c[8] = {{-a, -a, -a}, {a, -a, -a}, {-a, a, -a}, {a, a, -a},
                            {-a, -a, a},  {a, -a, a},  {-a, a, a},  {a, a, a}};
    quad(s, c[0], c[4], c[6], c[2]);
    quad(s, c[1], c[3], c[7], c[5]);
    quad(s, c[0], c[1], c[5], c[4]);
    quad(s, c[2], c[6], c[7], c[3]);
    quad(s, c[0], c[2], c[3], c[1]);
    quad(s, c[4], c[5], c[7], c[6]);
    s.computeBounds();
    EmbreeScene rt(s);
    Camera cam;
    cam.eye = {0.1f, 0.05f, 0.3f};
    cam.target = {-0.2f, -0.1f, -1.0f};
    cam.nearZ = 0.01f;
    cam.farZ = 10.0f;
    cam.fovYDeg = 90.0f;
    const ReferenceImage img = traceReference(rt, cam, 40, 30, {2.0f, 128});
    double sum = 0;
    for (size_t i = 0; i < img.ao.size(); ++i) {
        ASSERT_EQ(img.geometry[i], 1.0f);
        sum += img.ao[i] * img.ao[i];
    }
    EXPECT_LT(std::sqrt(sum / img.ao.size()), 0.01); // no ray leaks through edges or corners
}

TEST(Reference, CreasesOfInterpenetratingSlabsMatchTheClosedForm) {
    // builtin:slabs: slabs that pass through each other (as CornellBox's walls), seen so that the
    // centre row's pixel centres land exactly on the floor/back-wall crease. Before the hits were
    // backed off toward the eye, that row started every AO ray inside the other slab: AO 0.00.
    const Scene s = makeBuiltinScene("slabs");
    EmbreeScene rt(s);
    const Camera cam = *s.camera;
    const float R = 0.4f;
    const int w = 161, h = 121; // odd height: the centre row is the crease
    const ReferenceImage img = traceReference(rt, cam, w, h, {R, 1024});
    EXPECT_EQ(img.ambiguousPixels(), 0);
    double creaseSum = 0, creaseWorst = 0, beside = 0;
    long creaseN = 0, besideN = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (img.geometry[i] == 0.0f) continue;
            const glm::vec3 p = hitPosition(cam, w, h, x, y, img.depth[i]);
            // Away from the left wall and the slabs' far ends, the crease is a straight 90° wedge.
            if (p.x < 0.05f + R + 0.05f || p.x > 4.0f - R - 0.05f || p.y > 4.0f - R || p.z > 4.0f - R) continue;
            const bool floor = std::abs(p.y - 0.05f) < 1e-3f, wall = std::abs(p.z - 0.05f) < 1e-3f;
            ASSERT_TRUE(floor || wall) << x << "," << y;
            const double ao = img.ao[i];
            if (y == h / 2) {
                creaseSum += ao;
                creaseWorst = std::max(creaseWorst, std::abs(ao - 0.5));
                ++creaseN;
                continue;
            }
            const double d = std::max(0.0f, floor ? p.z - 0.05f : p.y - 0.05f);
            beside += (ao - wallClosedForm(d, R)) * (ao - wallClosedForm(d, R));
            ++besideN;
        }
    ASSERT_GT(creaseN, w / 3);
    ASSERT_GT(besideN, w * h / 3);
    const double creaseMean = creaseSum / creaseN, besideRmse = std::sqrt(beside / besideN);
    std::printf("slabs crease: mean AO %.4f (worst |AO - 0.5| %.4f) over %ld pixels; beside it RMSE %.4f "
                "over %ld pixels (1024 rays)\n",
                creaseMean, creaseWorst, creaseN, besideRmse, besideN);
    EXPECT_NEAR(creaseMean, 0.5, 0.02);
    EXPECT_LT(creaseWorst, 0.05); // each crease pixel, 1024 stratified rays
    EXPECT_LT(besideRmse, 0.02);
}

TEST(Reference, CornellBoxCreasesAreHalfOccluded) {
    // The shared CornellBox: five 0.1-thick slabs through each other, its camera centred, so the
    // diagonal wall/ceiling creases run through pixel centres. 69 pixels read 0.00 at 320x180
    // before the back-off; the closed form is 0.5.
    const Scene s = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf");
    ASSERT_TRUE(s.camera);
    EmbreeScene rt(s);
    const Camera cam = *s.camera;
    const int w = 320, h = 180;
    const float R = 0.873f; // 5 % of the diagonal
    const ReferenceImage img = traceReference(rt, cam, w, h, {R, 256});
    double sum = 0, worst = 1;
    long crease = 0, black = 0;
    const float inner = 4.95f; // the slabs' inner faces
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (img.geometry[i] == 0.0f) continue;
            black += img.ao[i] < 0.05f;
            const glm::vec3 p = hitPosition(cam, w, h, x, y, img.depth[i]);
            int onWall = 0, nearThird = 0;
            for (int a = 0; a < 3; ++a) {
                const float off = inner - std::abs(p[a]);
                onWall += std::abs(off) < 0.01f;
                nearThird += off > 0.01f && off < R + 0.1f;
            }
            // A straight crease, not a 3-way corner; the upper half (the floor's creases also see
            // the boxes standing near the walls).
            if (onWall != 2 || nearThird || p.z > 4.0f || p.y < 0.0f) continue;
            sum += img.ao[i];
            worst = std::min(worst, double(img.ao[i]));
            ++crease;
        }
    ASSERT_GT(crease, 40);
    std::printf("CornellBox creases: %ld pixels, mean AO %.4f, lowest %.4f; %ld pixels below 0.05 in all\n",
                crease, sum / crease, worst, black);
    EXPECT_NEAR(sum / crease, 0.5, 0.02);
    EXPECT_GT(worst, 0.4);
    EXPECT_LE(black, 3); // the sphere's contact with the floor
}

TEST(Reference, CoincidentFacesAreCountedAndLeftOutOfTheMetrics) {
    // Two unit floors 1e-4 apart (a face drawn twice), seen from 3000 units: the primary ray's
    // rounding (ULPs of its length: 2.4e-4) cannot order them, and the back-off toward the eye
    // (ULPs of the coordinates, ~1) does not clear the twin, so where the ray takes the lower one
    // every AO ray hits the twin just above (AO 0): a dash the geometry does not decide.
    Scene s;
    const float t = 1e-4f;
    quad(s, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1});
    quad(s, {-1, t, -1}, {-1, t, 1}, {1, t, 1}, {1, t, -1});
    s.draws.push_back({0, uint32_t(s.indices.size()), glm::vec4(1)});
    s.computeBounds();
    EmbreeScene rt(s);
    Camera cam = lookDown({0.0f, 0, 0.0f}, 3000.0f, 1.0f);
    cam.nearZ = 100.0f;
    cam.farZ = 5000.0f;
    const int w = 256, h = 192;
    const ReferenceImage img = traceReference(rt, cam, w, h, {0.5f, 16});
    long dark = 0, darkFlagged = 0, openFlagged = 0, geo = 0;
    for (size_t i = 0; i < img.ao.size(); ++i) {
        if (img.geometry[i] == 0.0f) continue;
        ++geo;
        const bool flagged = img.ambiguous[i] > 0.0f;
        if (img.ao[i] < 0.5f) {
            ++dark;
            darkFlagged += flagged;
        } else {
            openFlagged += flagged;
        }
    }
    std::printf("coincident floors: %ld of %ld pixels dark, %ld of them flagged; %ld open pixels flagged\n",
                dark, geo, darkFlagged, openFlagged);
    ASSERT_GT(dark, 0) << "the test needs the rounding to pick the lower face somewhere";
    EXPECT_EQ(darkFlagged, dark);          // every dash is counted...
    EXPECT_EQ(img.ambiguousPixels(), dark + openFlagged);
    EXPECT_LT(openFlagged, geo / 10);      // ...and little else
    // The metrics leave them out: an all-white estimate (the truth for a floor) is then exact.
    const std::vector<float> white(img.ao.size(), 1.0f);
    MetricsInput in{w, h, white.data(), img.ao.data(), img.geometry.data(), img.depth.data()};
    in.exclude = img.ambiguous.data();
    const ErrorMetrics m = computeErrorMetrics(in);
    EXPECT_EQ(m.excludedPixels, img.ambiguousPixels());
    EXPECT_EQ(m.geometryPixels + m.excludedPixels, geo);
    EXPECT_NEAR(m.rmse, 0.0, 1e-6);
    // An open plane near the camera has none.
    const Scene one = floorScene(false);
    EmbreeScene rt1(one);
    EXPECT_EQ(traceReference(rt1, lookDown({3, 0, -2}, 5.0f), 48, 32, {1.0f, 16}).ambiguousPixels(), 0);
}

TEST(Reference, BitIdenticalAcrossThreadCountsAndBatches) {
    const Scene s = floorScene(true);
    EmbreeScene rt(s);
    const Camera cam = lookDown({0.5f, 0, 0}, 1.5f);
    ReferenceSettings one{0.8f, 96, ReferenceVariant::Visibility, 1};
    ReferenceSettings two = one;
    two.threads = 2;
    const ReferenceImage a = traceReference(rt, cam, 40, 24, one);
    ReferenceTracer progressive(rt, cam, 40, 24, two);
    ASSERT_TRUE(progressive.addSamples(32));
    ASSERT_TRUE(progressive.addSamples(64));
    const ReferenceImage b = progressive.image();
    EXPECT_EQ(b.samples, 96);
    EXPECT_EQ(a.ao, b.ao);
    EXPECT_EQ(a.depth, b.depth);
    // And a different sample count is a different (but close) estimate.
    const ReferenceImage c = traceReference(rt, cam, 40, 24, {0.8f, 64});
    EXPECT_NE(a.ao, c.ao);
}

TEST(Reference, CancelStopsTheTracer) {
    const Scene s = floorScene(true);
    EmbreeScene rt(s);
    std::atomic<bool> cancel{true};
    ReferenceTracer t(rt, lookDown({0.5f, 0, 0}, 1.5f), 32, 32, {1.0f, 64});
    EXPECT_FALSE(t.addSamples(64, &cancel));
    EXPECT_THROW(t.addSamples(1), Error);
}

TEST(Reference, BadSettingsAreRefused) {
    const Scene s = floorScene(false);
    EmbreeScene rt(s);
    const Camera cam = lookDown({0, 0, 0}, 1.0f);
    EXPECT_THROW(ReferenceTracer(rt, cam, 8, 8, {0.0f, 8}), Error);
    EXPECT_THROW(ReferenceTracer(rt, cam, 8, 8, {NAN, 8}), Error);
    EXPECT_THROW(ReferenceTracer(rt, cam, 8, 8, {1.0f, 0}), Error);
    EXPECT_THROW(ReferenceTracer(rt, cam, 0, 8, {1.0f, 8}), Error);
    EXPECT_THROW(parseVariant("bent"), Error);
}

TEST(Reference, CacheReturnsTheSameFrameWithoutTracing) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/refcache";
    std::filesystem::remove_all(dir);
    const Scene s = floorScene(true);
    const Camera cam = lookDown({0.5f, 0, 0}, 1.5f);
    ReferenceProvider provider(s, dir);
    bool cached = true;
    const ReferenceImage first = provider.get(cam, 24, 16, {0.8f, 64}, {}, &cached);
    EXPECT_FALSE(cached);
    ReferenceProvider again(s, dir); // a new run: no BVH unless it misses
    const ReferenceImage second = again.get(cam, 24, 16, {0.8f, 64}, {}, &cached);
    EXPECT_TRUE(cached);
    EXPECT_EQ(first.ao, second.ao);
    EXPECT_EQ(first.stdErr, second.stdErr);
    EXPECT_EQ(first.depth, second.depth);
    EXPECT_EQ(second.samples, 64);
    // Any key change misses: radius, rays, variant, size, camera, scene content.
    again.get(cam, 24, 16, {0.81f, 64}, {}, &cached);
    EXPECT_FALSE(cached);
    again.get(cam, 24, 16, {0.8f, 64, ReferenceVariant::Obscurance}, {}, &cached);
    EXPECT_FALSE(cached);
    Scene moved = s;
    moved.vertices[0].position.x += 1e-3f;
    EXPECT_NE(sceneContentHash(moved), sceneContentHash(s));
}

TEST(Reference, ACorruptCacheEntryIsAMissNeverTrusted) {
    // Before: an EXR with AO 7.0 gave "RMSE 6.01" and exit 0; a json with samples 1e300 gave
    // rays_per_pixel -2147483648; a NaN ended in a bare json exception. Every entry is validated
    // (range, finiteness, size, key) and any bad one is traced again.
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/refcache_corrupt";
    std::filesystem::remove_all(dir);
    const Scene s = floorScene(true);
    const Camera cam = lookDown({0.5f, 0, 0}, 1.5f);
    const ReferenceSettings rs{0.8f, 32};
    const ReferenceImage good = ReferenceProvider(s, dir).get(cam, 24, 16, rs);
    const ReferenceKey key{sceneContentHash(s), cam, 24, 16, rs};
    const std::string stem = dir + "/" + key.fileStem();
    const std::string json = ssaotest::slurp(stem + ".json");
    const Image exr = readExr(stem + ".exr");
    auto corrupt = [&](const std::function<void(Image&, std::string&)>& f) {
        Image px = exr;
        std::string meta = json;
        f(px, meta);
        writeExr(px, stem + ".exr");
        ssaotest::writeTemp("refcache_meta.json", meta);
        std::filesystem::copy_file(std::string(SSAOLAB_TEST_TMP) + "/refcache_meta.json", stem + ".json",
                                   std::filesystem::copy_options::overwrite_existing);
        return loadCachedReference(key, dir).has_value();
    };
    EXPECT_TRUE(corrupt([](Image&, std::string&) {})); // the untouched entry loads
    EXPECT_FALSE(corrupt([](Image& px, std::string&) { px.data[0] = 7.0f; }));            // AO outside [0,1]
    EXPECT_FALSE(corrupt([](Image& px, std::string&) { px.data[0] = std::nanf(""); }));   // NaN AO
    EXPECT_FALSE(corrupt([](Image& px, std::string&) { px.data[2] = INFINITY; }));        // depth
    EXPECT_FALSE(corrupt([](Image& px, std::string&) { px.data[3] = 0.5f; }));            // geometry flag
    EXPECT_FALSE(corrupt([](Image& px, std::string&) { px.width = 12, px.data.resize(12 * 16 * 4); })); // size
    EXPECT_FALSE(corrupt([](Image&, std::string& m) {
        m.replace(m.find("\"samples\": 32"), 13, "\"samples\": 1e300");
    }));
    EXPECT_FALSE(corrupt([](Image&, std::string& m) { m = "[1, 2]"; })); // not an object
    EXPECT_FALSE(corrupt([](Image&, std::string& m) { m = "{\"key\": "; })); // truncated
    // And the provider traces again instead of returning the bad entry.
    corrupt([](Image& px, std::string&) { px.data[0] = 7.0f; });
    bool cached = true;
    const ReferenceImage again = ReferenceProvider(s, dir).get(cam, 24, 16, rs, {}, &cached);
    EXPECT_FALSE(cached);
    EXPECT_EQ(again.ao, good.ao);
}

TEST(Reference, AnEmptyXdgCacheHomeMeansUnset) {
    // XDG Base Directory: empty means unset. Before: XDG_CACHE_HOME="" put the cache at /ssaolab.
    const char* keepCache = std::getenv("SSAOLAB_CACHE_DIR");
    const std::string keep = keepCache ? keepCache : "";
    ::unsetenv("SSAOLAB_CACHE_DIR");
    ::setenv("XDG_CACHE_HOME", "", 1);
    ::setenv("HOME", "/home/someone", 1);
    EXPECT_EQ(referenceCacheDir(), "/home/someone/.cache/ssaolab/reference");
    ::setenv("SSAOLAB_CACHE_DIR", "", 1);
    EXPECT_EQ(referenceCacheDir(), "/home/someone/.cache/ssaolab/reference");
    ::setenv("XDG_CACHE_HOME", "/xdg", 1);
    EXPECT_EQ(referenceCacheDir(), "/xdg/ssaolab/reference");
    if (keepCache) ::setenv("SSAOLAB_CACHE_DIR", keep.c_str(), 1);
    else ::unsetenv("SSAOLAB_CACHE_DIR");
}
