// The guard band (gbuffer.guard_band_px, passes/guard_band_pass.h): positions beyond the frame on
// the same pixel grid, read by the taps that leave the frame. On builtin:corner looked at from
// straight above with the wall just outside the top edge, the floor near that edge is occluded in
// truth (the closed form beside a wall, closed_form.h); without a band every technique reads it
// open, with one the darkening comes back; far from the edge nothing changes, bit for bit.
#include "closed_form.h"
#include "scene/load/load_scene.h"
#include "gl_fixture.h"

#include "gl/readback.h"
#include "passes/guard_band_pass.h"
#include "scene/scene.h"
#include "techniques/technique.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace ssao;
using namespace ssaotest;

namespace {
class GuardBand : public GlTest {};

// Straight above the floor, the top of the frame toward the wall (z = -2): the inner-pixel test.
Camera aboveTheFloor() {
    Camera c;
    c.eye = {0.0f, 3.0f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    c.fovYDeg = 50.0f;
    c.nearZ = 0.1f;
    c.farZ = 50.0f;
    c.clip = ClipMode::Fixed;
    return c;
}

// Facing the wall from 4 units away, 1 unit up, pitched 41.4° down: the frame's top edge meets the
// floor at z = -1.4, 0.6 in front of the wall, and the wall rises just above the frame (its foot
// ~5 px beyond the edge, 1 unit up ~29 px: inside a 64 px band).
Camera facingTheWall() {
    Camera c = aboveTheFloor();
    c.eye = {0.0f, 1.0f, 2.0f};
    const float pitch = glm::radians(41.4f);
    c.target = c.eye + glm::vec3(0.0f, -std::sin(pitch), -std::cos(pitch));
    c.up = {0.0f, 1.0f, 0.0f};
    return c;
}
} // namespace

TEST_F(GuardBand, BringsBackTheWallJustOffScreenAndChangesNothingFarFromTheEdge) {
    // The floor near the frame's top edge is 0.6 from the wall face, within R = 1; the wall is
    // never in the frame. Every technique whose pass declares it reads the band.
    const Scene corner = loadScene("builtin:corner");
    int banded = 0;
    for (const auto& t : techniques()) {
        const std::string& id = t.id;
        Settings s = defaultSettings();
        s.ao.technique = id;
        s.ao.radiusMode = RadiusMode::World;
        s.ao.radius = 1.0f;
        s.denoise.kind = DenoiseKind::None; // the taps' own answer
        const Rendered none = render("builtin:corner", s, 160, 90, facingTheWall());
        s.gbuffer.guardBandPx = 64;
        auto r = makeRenderer(corner, s, 160, 90, facingTheWall());
        r->render();
        bool reads = false;
        for (const auto& pass : r->graph().passOrder())
            if (const PassDecl* d = r->graph().declaration(pass))
                reads |= std::count(d->reads.begin(), d->reads.end(), GuardBandPass::kOutput) > 0;
        if (!reads) continue; // its taps never read off the frame (the kernel's)
        ++banded;
        const Rendered band = readAll(*r);
        ASSERT_TRUE(finiteInRange(band.ao, 0.0f, 1.0f)) << id;
        double nearNone = 0, nearBand = 0, nearTruth = 0;
        long nearN = 0;
        float farDiff = 0;
        const glm::mat4 toWorld = glm::inverse(band.camera.view());
        for (size_t i = 0; i < band.ao.data.size(); ++i) {
            if (!(band.position.data[4 * i + 3] > 0.0f)) continue;
            const glm::vec3 p(toWorld * glm::vec4(band.position.data[4 * i], band.position.data[4 * i + 1],
                                                  band.position.data[4 * i + 2], 1.0f));
            if (p.y > 0.01f) continue; // the floor only
            if (p.z < -1.25f) {
                nearNone += none.ao.data[i], nearBand += band.ao.data[i], ++nearN;
                nearTruth += wallClosedForm(double(p.z) + 2.0, 1.0); // d = distance from the wall
            } else if (p.z > -0.3f && std::abs(p.x) < 1.0f) { // more than R from the top and side edges
                farDiff = std::max(farDiff, std::abs(band.ao.data[i] - none.ao.data[i]));
            }
        }
        ASSERT_GT(nearN, 100) << id;
        nearNone /= nearN, nearBand /= nearN, nearTruth /= nearN;
        std::printf("%-5s floor within 0.15 of the top edge: AO %.3f without a band, %.3f with 64 px, closed form %.3f\n",
                    id.c_str(), nearNone, nearBand, nearTruth);
        EXPECT_GT(nearNone, 0.97) << id << ": without a band the wall is unseen";
        // A technique within 0.1 of the closed form at its defaults (TechniqueInfo::cornerBound: GTAO,
        // the bitmask) integrates the visibility it is of; a falloff (SAO's, HBAO's, bounds 0.12-0.15)
        // weighs a wall 0.6 R away lightly, so the band's gain is smaller there, but it is a gain.
        const bool visibility = t.cornerBound <= 0.1;
        EXPECT_LT(nearBand, nearNone - (visibility ? 0.03 : 0.005)) << id << ": the band shows it";
        EXPECT_LT(std::abs(nearBand - nearTruth), std::abs(nearNone - nearTruth)) << id;
        EXPECT_LT(farDiff, 1e-3f) << id << ": far from the edges every tap stays in the frame";
    }
    EXPECT_GT(banded, 0) << "no technique reads the guard band";
}

TEST_F(GuardBand, TheWidenedProjectionKeepsThePixelGrid) {
    // Pixel (x, y) of the frame is pixel (x + g, y + g) of the band: the NDC of a point scales by
    // W / (W + 2g), which maps frame pixel centres onto band pixel centres.
    const glm::mat4 p = glm::perspective(glm::radians(50.0f), 160.0f / 90.0f, 0.1f, 50.0f);
    const glm::mat4 q = widenedProjection(p, 160, 90, 16);
    const glm::vec4 v(0.3f, -0.2f, -2.0f, 1.0f);
    const glm::vec4 a = p * v, b = q * v;
    const float xa = (a.x / a.w * 0.5f + 0.5f) * 160.0f, xb = (b.x / b.w * 0.5f + 0.5f) * 192.0f;
    const float ya = (a.y / a.w * 0.5f + 0.5f) * 90.0f, yb = (b.y / b.w * 0.5f + 0.5f) * 122.0f;
    EXPECT_NEAR(xb - xa, 16.0f, 1e-3f);
    EXPECT_NEAR(yb - ya, 16.0f, 1e-3f);
}

TEST_F(GuardBand, ItsInnerPixelsAreTheGBuffersPositions) {
    Settings s = defaultSettings();
    s.ao.technique = "gtao";
    s.gbuffer.guardBandPx = 16;
    const Scene scene = loadScene("builtin:corner");
    auto r = makeRenderer(scene, s, 160, 90, aboveTheFloor());
    r->render();
    const Image frame = readBack(r->texture("gbuffer.position"), 4);
    const Image band = readBack(r->texture(GuardBandPass::kOutput), 4);
    ASSERT_EQ(band.width, 160 + 32);
    ASSERT_EQ(band.height, 90 + 32);
    float worst = 0;
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x)
            for (int k = 0; k < 4; ++k)
                worst = std::max(worst, std::abs(frame.data[size_t(4 * (y * 160 + x) + k)] -
                                                 band.data[size_t(4 * ((y + 16) * 192 + x + 16) + k)]));
    EXPECT_LT(worst, 1e-4f);
    // Beyond the frame's top edge (read-back rows run top first): toward the wall at z = -2 (view y 2).
    float maxViewY = 0;
    for (int y = 0; y < 16; ++y)
        maxViewY = std::max(maxViewY, band.data[size_t(4 * (y * 192 + 96) + 1)]);
    EXPECT_GT(maxViewY, 1.5f) << "the band reaches toward the wall";
}

TEST_F(GuardBand, TheInspectorTellsWhichTapsReadTheBand) {
    // A floor pixel by the top edge, facing the wall just above the frame: without a band its taps
    // that leave the frame are off screen; with one they find the wall and say so.
    Settings s = defaultSettings();
    s.ao.technique = "vbao";
    s.ao.radiusMode = RadiusMode::World;
    s.ao.radius = 1.0f;
    const Scene scene = loadScene("builtin:corner");
    int counts[2][2] = {}; // [band][from band, off screen]
    for (int b = 0; b < 2; ++b) {
        s.gbuffer.guardBandPx = b ? 64 : 0;
        auto r = makeRenderer(scene, s, 160, 90, facingTheWall());
        r->render();
        const std::optional<PixelInspection> pi = r->inspect(0, {80, 87}); // GL origin: 3 rows below the top
        ASSERT_TRUE(pi && pi->geometry);
        for (const InspectTap& t : pi->taps)
            counts[b][0] += fromGuardBand(t), counts[b][1] += t.state == TapState::Offscreen;
    }
    EXPECT_EQ(counts[0][0], 0);
    EXPECT_GT(counts[0][1], 0) << "without a band the taps above the frame see nothing";
    EXPECT_GT(counts[1][0], 0) << "with one they read it";
    EXPECT_LT(counts[1][1], counts[0][1]);
}
