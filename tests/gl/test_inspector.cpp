// The CPU replay of the SSAO shader (sample inspector) must reproduce the GPU's AO.
#include "gl_fixture.h"

#include "scene/scene.h"
#include "ssao/constants.h"
#include "ssao/sample_inspector.h"

#include <cmath>

using namespace ssao;
using namespace ssaotest;

namespace {
class Inspector : public GlTest {};
} // namespace

TEST_F(Inspector, CpuReplayMatchesGpuAoForEveryMode) {
    const char* modes[] = {"",
                           "ssao.kernel=sphere",
                           "ssao.separable=true",
                           "ssao.position_source=depth",
                           "gbuffer.normal_format=rgba8",
                           "ssao.range_check=hard",
                           "ssao.depth_test=fragment",
                           "ssao.noise=none",
                           "ssao.offscreen=clamp",
                           "ssao.power=2.5"};
    for (const char* mode : modes) {
        Settings s = defaultSettings();
        s.ssao.samples = 32;
        if (*mode) applyAssignment(s, mode);
        Scene scene = loadScene("builtin:showcase");
        const int w = 96, h = 54;
        auto rp = makeRenderer(scene, s, w, h);
        Renderer& r = *rp;
        r.render();
        Image pos = readBack(r.gbuffer().position(), 4), nrm = readBack(r.gbuffer().normal(), 3);
        Image dep = readBack(r.gbuffer().depth(), 1), ao = readBack(r.ssao().aoRaw(), 1);
        GBufferImages gb{&pos, &nrm, &dep};
        const gpu::FrameConstants fc = packFrameConstants(*scene.camera, w, h, scene.bounds.radius());
        int close = 0, total = 0, geometry = 0;
        double sumErr = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                PixelInspection pi = inspectPixel(s.ssao, s.gbuffer, fc, gb, x, y);
                float gpu = ao.at(x, y);
                float err = std::abs(pi.ao - gpu);
                sumErr += err;
                // One sample flipping at a threshold (float rounding) moves AO by 1/N (1/2N separable).
                close += err <= 1.01f / float(s.ssao.samples) + 1e-4f;
                geometry += pi.geometry;
                ++total;
            }
        EXPECT_GT(geometry, total / 3) << mode;
        EXPECT_GE(close, int(0.97 * total)) << mode << ": " << close << " of " << total;
        EXPECT_LT(sumErr / total, 0.003) << mode;
    }
}

TEST_F(Inspector, TapsReportWhereSamplesLandAndWhy) {
    Settings s = defaultSettings();
    s.ssao.noise = Noise::None;
    s.ssao.radius = 1.0f;
    Scene scene = loadScene("builtin:corner");
    auto rp = makeRenderer(scene, s, 320, 240);
    Renderer& r = *rp;
    r.render();
    Image pos = readBack(r.gbuffer().position(), 4), nrm = readBack(r.gbuffer().normal(), 3),
          dep = readBack(r.gbuffer().depth(), 1);
    GBufferImages gb{&pos, &nrm, &dep};
    const gpu::FrameConstants fc = packFrameConstants(*scene.camera, 320, 240, scene.bounds.radius());
    // Find the floor pixel right at the wall in the centre column: half its hemisphere is wall.
    int yWall = -1;
    for (int y = 239; y >= 0; --y)
        if (std::abs(nrm.at(160, y, 1) - nrm.at(160, 239, 1)) > 0.2f) {
            yWall = y + 1;
            break;
        }
    ASSERT_GT(yWall, 0);
    PixelInspection pi = inspectPixel(s.ssao, s.gbuffer, fc, gb, 160, yWall);
    ASSERT_TRUE(pi.geometry);
    ASSERT_EQ(pi.taps.size(), 64u);
    int occluded = 0;
    for (auto& t : pi.taps) {
        occluded += t.state == SampleTap::State::Occluded;
        EXPECT_LE(glm::length(t.viewPos - pi.position), s.ssao.radius + 1e-4f); // inside the kernel radius
    }
    std::printf("floor pixel next to the wall: %d of 64 taps occluded, AO %.3f\n", occluded, pi.ao);
    EXPECT_GT(occluded, 6);
    EXPECT_LT(pi.ao, 0.9f);
    EXPECT_NEAR(pi.ao, readBack(r.ssao().aoRaw(), 1).at(160, yWall), 1.01f / 64.0f);
}
