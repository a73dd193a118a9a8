// The sample inspector shows what the GPU did: the AO shader itself, compiled with INSPECT and run
// for one pixel, records its taps. The record must reproduce the value the pass wrote.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "techniques/gtao/settings.h"

#include "scene/scene.h"
#include "techniques/technique.h"
#include "util/error.h"

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace ssao;
using namespace ssaotest;

namespace {
class Inspector : public GlTest {};
} // namespace

TEST_F(Inspector, GpuTapsReproduceTheWrittenAoForEveryModeAndTechnique) {
    const char* modes[] = {"",
                           "kernel.shape=sphere",
                           "kernel.separable=true",
                           "kernel.position_source=depth",
                           "gbuffer.normal_format=rgba8",
                           "kernel.range_check=hard",
                           "kernel.range_check=off",
                           "kernel.depth_test=fragment",
                           "kernel.noise=none",
                           "kernel.offscreen=clamp",
                           "ao.power=2.5",
                           "ao.radius_mode=screen",
                           "ao.resolution=half"};
    const Scene scene = loadScene("builtin:showcase");
    for (const auto& t : techniques())
        for (const char* mode : modes) {
            Settings s = defaultSettings();
            s.ao.technique = t.id;
            s.kernel.samples = 24;
            if (*mode) applyAssignment(s, mode);
            const int w = 96, h = 54;
            auto r = makeRenderer(scene, s, w, h);
            r->render();
            const Image ao = readBack(r->texture("ao.raw"), 1);
            int geometry = 0, checked = 0;
            for (int y = 1; y < h; y += 4)
                for (int x = 2; x < w; x += 5) {
                    const auto pi = r->inspect(0, {x, y});
                    ASSERT_TRUE(pi.has_value()) << mode;
                    const glm::ivec2 p = pi->pixel; // in the AO buffer's own resolution
                    const float written = ao.at(p.x, p.y);
                    // The same program but for the record writes: the same float, bit for bit or nearly.
                    EXPECT_NEAR(pi->ao, written, 1e-5f) << t.id << " " << mode << " at " << x << "," << y;
                    ++checked;
                    if (!pi->geometry) {
                        EXPECT_TRUE(pi->taps.empty());
                        EXPECT_EQ(written, 1.0f);
                        continue;
                    }
                    ++geometry;
                    if (t.id == "gtao") {
                        // Every step of every slice on both sides is recorded; a tap's contribution
                        // is its falloff weight (the horizon, not a sum, decides the occlusion).
                        int slices = 0, steps = 0;
                        gtaoSlicesSteps(s.gtao, slices, steps);
                        EXPECT_EQ(int(pi->taps.size()), slices * steps * 2) << mode;
                        for (const auto& tap : pi->taps)
                            EXPECT_TRUE(tap.contribution >= 0.0f && tap.contribution <= 1.0f) << mode;
                        const float vis = std::clamp(1.0f - pi->occlusion, 0.0f, 1.0f);
                        EXPECT_NEAR(std::pow(vis, s.ao.power), pi->ao, 1e-4f) << mode;
                        continue;
                    }
                    if (t.id == "vbao") {
                        // Every sample is recorded with the fraction of the slice's 32 sectors it hides;
                        // the mask (their union, cosine-weighted), not a sum, decides the occlusion.
                        EXPECT_EQ(int(pi->taps.size()), s.vbao.slices * s.vbao.steps * 2) << mode;
                        for (const auto& tap : pi->taps)
                            EXPECT_TRUE(tap.contribution >= 0.0f && tap.contribution <= 1.0f) << mode;
                        const float vis = std::clamp(1.0f - pi->occlusion, 0.0f, 1.0f);
                        EXPECT_NEAR(std::pow(vis, s.ao.power), pi->ao, 1e-4f) << mode;
                        continue;
                    }
                    // The taps add up to what the shader accumulated.
                    double sum = 0;
                    for (const auto& tap : pi->taps)
                        sum += tap.contribution;
                    EXPECT_NEAR(sum, pi->occlusion, 1e-3) << mode;
                    if (t.id == "kernel") {
                        EXPECT_EQ(int(pi->taps.size()), s.kernel.samples * (s.kernel.separable ? 2 : 1))
                            << mode;
                        const float vis = std::clamp(1.0f - pi->occlusion / pi->normaliser, 0.0f, 1.0f);
                        EXPECT_NEAR(std::pow(vis, s.ao.power), pi->ao, 1e-4f) << mode;
                    }
                }
            EXPECT_GT(geometry, checked / 3) << mode;
        }
}

TEST_F(Inspector, TapsReportWhereSamplesLandAndWhy) {
    Settings s = defaultSettings();
    s.kernel.noise = Noise::None;
    setParam(s, "ao.radius_mode", "world");
    s.ao.radius = 1.0f;
    const Scene scene = loadScene("builtin:corner");
    auto r = makeRenderer(scene, s, 320, 240);
    r->render();
    const Image nrm = readBack(r->texture("gbuffer.normal"), 3);
    // Find the floor pixel right at the wall in the centre column: half its hemisphere is wall.
    int yWall = -1;
    for (int y = 239; y >= 0; --y)
        if (std::abs(nrm.at(160, y, 1) - nrm.at(160, 239, 1)) > 0.2f) {
            yWall = y + 1;
            break;
        }
    ASSERT_GT(yWall, 0);
    const auto pi = r->inspect(0, {160, yWall});
    ASSERT_TRUE(pi && pi->geometry);
    ASSERT_EQ(pi->taps.size(), 64u);
    EXPECT_FLOAT_EQ(pi->radius, 1.0f);
    int occluded = 0;
    for (auto& t : pi->taps) {
        occluded += t.state == TapState::Occluded;
        EXPECT_LE(glm::length(t.viewPos - pi->position), s.ao.radius + 1e-4f); // inside the kernel radius
        EXPECT_GE(t.uv.x, 0.0f);
        EXPECT_LE(t.uv.x, 1.0f);
    }
    std::printf("floor pixel next to the wall: %d of 64 taps occluded, AO %.3f\n", occluded, pi->ao);
    EXPECT_GT(occluded, 6);
    EXPECT_LT(pi->ao, 0.9f);
    // A sky pixel records no taps; a pixel outside the image is refused.
    EXPECT_FALSE(r->inspect(0, {-1, 5}).has_value());
    EXPECT_FALSE(r->inspect(0, {320, 5}).has_value());
}

TEST_F(Inspector, ChainBIsInspectedWithItsOwnSettings) {
    const Scene scene = loadScene("builtin:showcase");
    Settings a = defaultSettings(), b = a;
    b.kernel.samples = 8;
    auto r = makeRenderer(scene, a, 96, 54);
    r->setSettingsB(b);
    r->render();
    const auto pa = r->inspect(0, {48, 40}), pb = r->inspect(1, {48, 40});
    ASSERT_TRUE(pa && pb && pa->geometry);
    EXPECT_EQ(pa->taps.size(), 64u);
    EXPECT_EQ(pb->taps.size(), 8u);
    EXPECT_NEAR(pb->ao, readBack(r->texture("b.ao.raw"), 1).at(48, 40), 1e-5f);
}

TEST_F(Inspector, OddSizesAtHalfResolutionMapPixelCentres) {
    // 97x55 at half resolution: 49x28 AO texels. Each G-buffer pixel maps to the texel holding its
    // centre, and the record is that texel's value.
    Settings s = defaultSettings();
    setParam(s, "ao.resolution", "half");
    s.kernel.samples = 8;
    auto r = makeRenderer(loadScene("builtin:showcase"), s, 97, 55);
    r->render();
    const Image ao = readBack(r->texture("ao.raw"), 1);
    ASSERT_EQ(ao.width, 49);
    for (int x : {0, 1, 2, 3, 48, 95, 96}) {
        const auto pi = r->inspect(0, {x, 40});
        ASSERT_TRUE(pi.has_value());
        EXPECT_EQ(pi->pixel.x, int((x + 0.5) * 49 / 97)) << x;
        EXPECT_NEAR(pi->ao, ao.at(pi->pixel.x, pi->pixel.y), 1e-5f) << x;
    }
}

TEST_F(Inspector, AFailingInspectVariantLeavesNoScissorBehind) {
    // The INSPECT variant of a broken shader folder does not compile: the inspector throws, and the
    // next frame must still cover every pixel (no 1x1 scissor left enabled).
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/inspect_shaders";
    std::filesystem::remove_all(dir);
    std::filesystem::copy(SSAOLAB_SHADER_DIR, dir, std::filesystem::copy_options::recursive);
    { std::ofstream(dir + "/include/inspect.glsl", std::ios::app) << "\n#ifdef INSPECT\nbroken;\n#endif\n"; }
    const Scene scene = loadScene("builtin:showcase");
    auto r = std::make_unique<Renderer>(dir);
    r->setSize(64, 36);
    r->setScene(scene);
    r->setCamera(*scene.camera);
    r->render();
    EXPECT_THROW(r->inspect(0, {32, 30}), Error);
    EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
    Settings s = r->settings();
    s.kernel.samples = 16;
    r->setSettings(s);
    r->render();
    const Image ao = readBack(r->texture("ao.raw"), 1);
    const Image mask = readBack(r->texture("gbuffer.depth"), 1);
    EXPECT_LT(stats(ao, &mask).min, 0.95) << "the AO pass drew the whole frame, not one pixel";
}

TEST_F(Inspector, ScreenRadiusIsInDisplayedPixelsWhateverTheRenderScale) {
    // While the app renders at 0.5 of the view, a 20-pixel radius is still 20 displayed pixels:
    // the same world radius as at full size.
    Settings s = defaultSettings();
    setParam(s, "ao.radius_mode", "screen");
    setParam(s, "ao.radius_px", "20");
    const Scene scene = loadScene("builtin:plane");
    auto full = makeRenderer(scene, s, 320, 180), half = makeRenderer(scene, s, 160, 90);
    half->setDisplayScale(0.5f);
    full->render();
    half->render();
    const auto a = full->inspect(0, {160, 120}), b = half->inspect(0, {80, 60});
    ASSERT_TRUE(a && b && a->geometry && b->geometry);
    EXPECT_NEAR(b->radius / -b->position.z, a->radius / -a->position.z, 0.02f * a->radius / -a->position.z);
    EXPECT_NEAR(half->radiusAtCentre().pixels, full->radiusAtCentre().pixels, 0.5f);
}
