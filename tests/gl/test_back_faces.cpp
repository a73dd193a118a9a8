// The back-face layer (gbuffer.back_faces, passes/back_face_pass.h): the far side of closed
// objects as a linear depth; the bitmask's solids then reach at least as deep as they are.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"

#include "gl/readback.h"
#include "passes/back_face_pass.h"
#include "scene/scene.h"

#include <cmath>

using namespace ssao;
using namespace ssaotest;

namespace {
class BackFaces : public GlTest {};
} // namespace

TEST_F(BackFaces, HoldTheFarSideOfTheWallAndNeverBrightenTheBitmask) {
    // builtin:corner's wall is a box 0.2 thick (z in [-2.2, -2.0]) seen from its own camera: where a
    // pixel shows the wall's face (normal +z), the back layer lies 0.2 / cos(view angle) behind it.
    Settings s = defaultSettings();
    s.ao.technique = "vbao";
    s.gbuffer.backFaces = true;
    const Scene scene = loadScene("builtin:corner");
    auto r = makeRenderer(scene, s, 160, 90);
    r->render();
    const Image depth = readBack(r->texture("gbuffer.depth"), 1);
    const Image back = readBack(r->texture(BackFacePass::kOutput), 1);
    const Image normal = readBack(r->texture("gbuffer.normal"), 3);
    const Image pos = readBack(r->texture("gbuffer.position"), 4);
    const glm::mat3 toWorld = glm::mat3(glm::inverse(r->camera().view()));
    long wall = 0, right = 0;
    for (size_t i = 0; i < depth.data.size(); ++i) {
        if (!(depth.data[i] > 0.0f)) continue;
        const glm::vec3 n = toWorld * glm::vec3(normal.data[3 * i], normal.data[3 * i + 1], normal.data[3 * i + 2]);
        if (n.z < 0.99f) continue; // the wall's face
        ++wall;
        const glm::vec3 p(pos.data[4 * i], pos.data[4 * i + 1], pos.data[4 * i + 2]);
        // Along the view ray through p the far face is 0.2 / cos further in world z; its linear
        // depth is the front's scaled by the ray length ratio.
        const float cosZ = std::abs(glm::dot(glm::normalize(toWorld * p), glm::vec3(0, 0, -1)));
        const float expected = depth.data[i] * (1.0f + 0.2f / (cosZ * glm::length(p)));
        right += std::abs(back.data[i] - expected) < 0.02f * expected;
    }
    ASSERT_GT(wall, 500);
    EXPECT_GT(double(right), 0.95 * double(wall)) << right << " of " << wall;

    // Never brighter: a tap's solid reaches at least the assumed thickness (aoBackGap).
    for (const char* name : {"builtin:showcase", "builtin:corner"}) {
        const Scene sc = loadScene(name);
        Settings off = s;
        off.gbuffer.backFaces = false;
        const Rendered a = render(name, off, 160, 90), b = render(name, s, 160, 90);
        float brighter = 0;
        for (size_t i = 0; i < a.aoRaw.data.size(); ++i)
            brighter = std::max(brighter, b.aoRaw.data[i] - a.aoRaw.data[i]);
        EXPECT_LT(brighter, 1e-5f) << name;
        EXPECT_TRUE(finiteInRange(b.ao, 0.0f, 1.0f)) << name;
    }
}

TEST_F(BackFaces, TheInspectorShowsWhichTapsReadTheBackLayer) {
    // builtin:corner's wall is 0.2 thick; with an assumed thickness of 0.05 R the back layer holds a
    // solid deeper than assumed behind every tap on the wall: those taps say so (inspection.h
    // backLayer, SSAO_TAP_BACK_LAYER), and none does without the layer.
    const Scene scene = loadScene("builtin:corner");
    for (bool on : {false, true}) {
        Settings s = defaultSettings();
        s.ao.technique = "vbao";
        s.vbao.thickness = 0.05f;
        s.gbuffer.backFaces = on;
        auto r = makeRenderer(scene, s, 160, 90);
        r->render();
        long taps = 0, fromBack = 0, states = 0;
        for (int y = 10; y < 90; y += 10)
            for (int x = 10; x < 160; x += 10) {
                const auto pi = r->inspect(0, {x, y});
                if (!pi || !pi->geometry) continue;
                for (const InspectTap& t : pi->taps) {
                    ++taps;
                    fromBack += t.backLayer;
                    states += int(t.state) <= int(TapState::Sky); // the layer bit does not leak into the state
                }
            }
        ASSERT_GT(taps, 1000);
        EXPECT_EQ(states, taps);
        if (on)
            EXPECT_GT(fromBack, taps / 20) << fromBack << " of " << taps;
        else
            EXPECT_EQ(fromBack, 0);
    }
}

TEST_F(BackFaces, TheTrueThicknessOnlyEverOpensSectorsAndKeepsAnOpenPlaneOpen) {
    // vbao.true_thickness: a solid ends at its far side even short of the assumed thickness, so
    // against the assumed depth it can only open sectors, never close one.
    Settings assumed = defaultSettings();
    assumed.ao.technique = "vbao";
    assumed.gbuffer.backFaces = true;
    assumed.vbao.thickness = 4.0f; // deeper than builtin:corner's 0.2 wall at R = 0.5
    Settings exact = assumed;
    exact.vbao.trueThickness = true;
    for (const char* name : {"builtin:showcase", "builtin:corner"}) {
        const Rendered a = render(name, assumed, 160, 90), b = render(name, exact, 160, 90);
        float darker = 0, brighter = 0;
        for (size_t i = 0; i < a.aoRaw.data.size(); ++i) {
            darker = std::max(darker, a.aoRaw.data[i] - b.aoRaw.data[i]);
            brighter = std::max(brighter, b.aoRaw.data[i] - a.aoRaw.data[i]);
        }
        EXPECT_LT(darker, 1e-5f) << name;
        EXPECT_TRUE(finiteInRange(b.ao, 0.0f, 1.0f)) << name;
        std::printf("%s: the true thickness opens up to %.3f of a pixel's AO\n", name, brighter);
        if (std::string(name) == "builtin:corner") EXPECT_GT(brighter, 0.01f); // light behind the thin wall
    }
    const Rendered plane = render("builtin:plane", exact, 96, 54);
    for (size_t i = 0; i < plane.aoRaw.data.size(); ++i)
        if (plane.depth.data[i] > 0.0f) ASSERT_GT(plane.aoRaw.data[i], 0.999f) << i; // geometry pixels
}
