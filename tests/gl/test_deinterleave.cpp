// ao.deinterleave (techniques/deinterleave.h): the layers hold the frame's pixels where their
// mapping says, ao.raw gets each layer's result at its own pixel, the AO stays the technique's
// (its physics at every level: test_physics_limits.cpp), and the setting is inert where it does not apply.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"

#include "scene/scene.h"
#include "techniques/deinterleave.h"
#include "techniques/technique.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace ssao;
using namespace ssaotest;

namespace {
class Deinterleave : public GlTest {};

// Its medium preset (its defaults before `make presets` made one).
Settings withTechnique(const std::string& id, bool on) {
    const bool shipped = std::filesystem::exists(std::string(SSAOLAB_ASSET_DIR) + "/presets/" + id + "-medium.json");
    Settings s = defaultSettings();
    s.ao.technique = id;
    if (shipped) s = preset(id + "-medium");
    s.ao.deinterleave = on;
    return s;
}

// The techniques whose shader runs over the layers (TechniqueInfo::deinterleave).
std::vector<std::string> deinterleaving() {
    std::vector<std::string> ids;
    for (const auto& t : techniques())
        if (t.deinterleave) ids.push_back(t.id);
    return ids;
}
} // namespace

TEST_F(Deinterleave, LayerUvsMapBackToTheirPixels) {
    // Layer l's texel (x, y) is the frame's pixel (4x + i, 4y + j): its centre, as a uv of the frame.
    const int w = 322, h = 183; // not multiples of 4: the last layer texels lie past the frame
    const glm::ivec2 size = Deinterleaver::layerSize(w, h);
    EXPECT_EQ(size, glm::ivec2(81, 46));
    for (int l = 0; l < Deinterleaver::kLayers; ++l) {
        const glm::ivec2 c = Deinterleaver::cell(l);
        for (glm::ivec2 t : {glm::ivec2(0, 0), glm::ivec2(7, 3), glm::ivec2(80, 45)}) {
            const glm::vec2 uv = Deinterleaver::frameUv((glm::vec2(t) + 0.5f) / glm::vec2(size), l, w, h);
            const glm::vec2 pixel = uv * glm::vec2(float(w), float(h)) - 0.5f;
            EXPECT_NEAR(pixel.x, float(4 * t.x + c.x), 1e-3f) << l;
            EXPECT_NEAR(pixel.y, float(4 * t.y + c.y), 1e-3f) << l;
        }
    }
    gpu::FrameConstants frame{};
    frame.viewport = glm::vec4(float(w), float(h), 1.0f / float(w), 1.0f / float(h));
    frame.proj[1][1] = 1.7f;
    const gpu::FrameConstants f = Deinterleaver::layerFrame(frame, size);
    EXPECT_EQ(f.viewport, glm::vec4(81.0f, 46.0f, 1.0f / 81.0f, 1.0f / 46.0f));
    // Pixels per unit (proj[1][1] viewport.y / 2) a quarter of the frame's, though 46 > 183 / 4.
    EXPECT_NEAR(f.proj[1][1] * f.viewport.y, 1.7f * float(h) / 4.0f, 1e-4f);
}

TEST_F(Deinterleave, EachPixelIsComputedFromItsOwnPositionAndWrittenBackToItself) {
    // The inspector replays the pass for one pixel in its layer: the position it read there must
    // be the G-buffer's at that pixel (the split), and the AO it computed the value ao.raw holds
    // there (the merge) - at every residue mod 4 and at the frame's last rows and columns.
    const Scene scene = loadScene(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf");
    ASSERT_FALSE(deinterleaving().empty());
    for (const std::string& tech : deinterleaving()) {
        const int w = 322, h = 183;
        auto r = makeRenderer(scene, withTechnique(tech, true), w, h);
        r->render();
        // Another size and back (the app's moving and still frames): the layers of this size return.
        r->setSize(160, 90), r->render(), r->setSize(w, h), r->render();
        const Rendered out = readAll(*r);
        int checked = 0;
        std::vector<int> xs = {0, 1, 2, 3, w - 4, w - 3, w - 2, w - 1}, ys = {0, 1, 2, 3, h - 4, h - 3, h - 2, h - 1};
        for (int x = 5; x < w - 4; x += 13) xs.push_back(x);
        for (int y = 5; y < h - 4; y += 11) ys.push_back(y);
        for (int y : ys)
            for (int x : xs) {
                const auto in = r->inspect(0, glm::ivec2(x, y));
                ASSERT_TRUE(in.has_value()) << tech;
                const int row = y; // readBack stores rows from the top, as the inspector counts them
                if (out.position.at(x, row, 3) == 0.0f) continue; // sky: nothing recorded
                ++checked;
                for (int k = 0; k < 3; ++k)
                    EXPECT_EQ(in->position[k], out.position.at(x, row, k)) << tech << " " << x << "," << y;
                EXPECT_EQ(in->ao, out.aoRaw.at(x, row)) << tech << " " << x << "," << y;
            }
        EXPECT_GT(checked, 100) << tech;
    }
}

TEST_F(Deinterleave, SharedScenesKeepTheirAo) {
    // The same technique over layers, its taps on a 4-pixel grid whose first step is 4 pixels out
    // (as gl_ssao's): it loses the occlusion nearer than that (creases lighter; the error against
    // the reference: docs/benchmarks.md, `ssaolab skips`), never adds any. Measured at 320x180:
    // mean AO up to 0.049 lighter (FlightHelmet, vbao), never more than 0.015 darker (gtao).
    for (const char* name : {"CornellBox/cornellBox.gltf", "2CylinderEngine/2CylinderEngine.gltf",
                             "Lantern/Lantern.gltf", "FlightHelmet/FlightHelmet.gltf"})
        for (const std::string& tech : deinterleaving()) {
            const std::string path = std::string(SSAOLAB_SCENES_DIR) + "/" + name;
            const Rendered off = render(path, withTechnique(tech, false), 320, 180);
            const Rendered on = render(path, withTechnique(tech, true), 320, 180);
            EXPECT_TRUE(finiteInRange(on.aoRaw, 0.0f, 1.0f)) << name << " " << tech;
            const double a = geometryMean(off, off.aoRaw), b = geometryMean(on, on.aoRaw);
            std::printf("%-40s %-4s mean AO %.4f interleaved, %.4f deinterleaved\n", name, tech.c_str(), a, b);
            EXPECT_GT(b, a - 0.02) << name << " " << tech;
            EXPECT_LT(b, a + 0.06) << name << " " << tech;
            EXPECT_GT(meanAbsDiff(off.aoRaw, on.aoRaw), 0.0) << "the layered pass ran: " << name << " " << tech;
        }
}

TEST_F(Deinterleave, InertWhereItDoesNotApply) {
    // Half-resolution AO, SAO (no slice march) and the guard band: the setting changes nothing.
    auto same = [](Settings s) {
        Settings on = s;
        on.ao.deinterleave = true;
        EXPECT_FALSE(deinterleaves(on));
        const Rendered a = render("builtin:showcase", s, 160, 90), b = render("builtin:showcase", on, 160, 90);
        return maxAbsDiff(a.aoRaw, b.aoRaw) == 0.0;
    };
    Settings half = withTechnique("vbao", false);
    half.ao.resolution = AoResolution::Half;
    EXPECT_TRUE(same(half));
    EXPECT_TRUE(same(preset("sao-medium")));
    Settings band = withTechnique("gtao", false);
    band.gbuffer.guardBandPx = 16;
    EXPECT_TRUE(same(band));
}
