// Work a frame does not need is skipped, and skipping it changes nothing (skip.* rows): sky pixels,
// meshes outside the view, G-buffer targets nobody reads, and passes whose inputs did not change.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "gl/readback.h"

#include "scene/gpu/gpu_scene.h"
#include "scene/scene.h"
#include "techniques/technique.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
class Skips : public GlTest {};
} // namespace

TEST_F(Skips, SkyPixelsCostNothingAndSkippingThemChangesNoGeometryPixel) {
    const Scene scene = loadScene("builtin:showcase");
    for (const auto& t : techniques()) {
        const std::string& tech = t.id;
        Settings s = defaultSettings();
        s.ao.technique = tech;
        auto r = makeRenderer(scene, s, 160, 90);
        r->render();
        const Rendered with = readAll(*r);
        s.skip.sky = false;
        r->setSettings(s);
        r->render();
        const Rendered without = readAll(*r);
        const Image mask = with.position.channel(3);
        EXPECT_EQ(maxAbsDiff(with.aoRaw, without.aoRaw), 0.0) << tech;
        EXPECT_EQ(maxAbsDiff(with.ao, without.ao, &mask), 0.0) << tech;
    }
}

namespace {
std::set<std::string> ranSet(const FrameReport& f) {
    const auto v = f.ran();
    return {v.begin(), v.end()};
}
} // namespace

TEST_F(Skips, EachChangeReRunsOnlyThePassesThatDependOnIt) {
    // camera -> everything; an AO setting -> AO and after; a denoise setting -> denoise and after;
    // a composite setting -> composite; nothing (a view switch, an idle frame) -> nothing. The
    // incremental frame equals a frame where every pass is forced.
    const Scene scene = loadScene("builtin:showcase");
    Settings s = defaultSettings();
    auto r = makeRenderer(scene, s, 160, 90);
    r->render();
    struct Change {
        const char* what;
        std::function<void()> apply;
        std::set<std::string> expect;
    };
    Camera moved = sceneCamera(scene);
    moved.eye += glm::vec3(0.1f, 0.0f, 0.0f);
    const std::vector<Change> changes = {
        {"camera", [&] { r->setCamera(moved); }, {"gbuffer", "ao", "denoise", "composite"}},
        {"ao.power", [&] { s.ao.power = 1.5f, r->setSettings(s); }, {"ao", "denoise", "composite"}},
        {"denoise.kind", [&] { s.denoise.kind = DenoiseKind::Gaussian, r->setSettings(s); }, {"denoise", "composite"}},
        {"composite.light", [&] { s.composite.light = 0.3f, r->setSettings(s); }, {"composite"}},
        // A pass keyed on one row of a group ("skip.sky") ignores the group's other rows.
        {"skip.sky", [&] { s.skip.sky = false, r->setSettings(s); }, {"ao", "denoise", "composite"}},
        {"nothing", [] {}, {}},
    };
    for (const Change& c : changes) {
        c.apply();
        EXPECT_EQ(ranSet(r->render()), c.expect) << c.what;
        const Image incremental = readBack(r->texture("composite"), 3);
        r->invalidate();
        EXPECT_EQ(r->render().ran().size(), 4u);
        EXPECT_EQ(maxAbsDiff(readBack(r->texture("composite"), 3), incremental), 0.0) << c.what;
    }
}

TEST_F(Skips, MeshesOutsideTheViewAreNotDrawn) {
    // ReciprocatingSaw close up: most parts lie outside the view. Culling counts them and changes
    // no pixel of the G-buffer.
    const std::string path = std::string(SSAOLAB_SCENES_DIR) + "/ReciprocatingSaw/ReciprocatingSaw.gltf";
    const Scene scene = loadScene(path);
    Camera close = sceneCamera(scene);
    close.eye = close.eye + 0.8f * (close.target - close.eye);
    Settings s = defaultSettings();
    s.skip.occluded = false; // the draws counted alike: this skip alone (test_occlusion.cpp has the other)
    auto r = makeRenderer(scene, s, 240, 135, close);
    r->render();
    const Rendered culled = readAll(*r);
    std::map<std::string, double> on = gbufferCounters(*r);
    s.skip.cull = false;
    r->setSettings(s);
    r->render();
    const Rendered all = readAll(*r);
    std::map<std::string, double> off = gbufferCounters(*r);
    std::printf("saw close up: %g of %g draws culled (%g of %g triangles)\n", on["draws_culled"],
                on["draws"] + on["draws_culled"], on["triangles_culled"], on["triangles"] + on["triangles_culled"]);
    EXPECT_EQ(off["draws_culled"], 0.0);
    EXPECT_EQ(on["draws"] + on["draws_culled"], off["draws"]);
    EXPECT_GT(on["draws_culled"], 0.25 * off["draws"]);
    EXPECT_EQ(maxAbsDiff(culled.position, all.position), 0.0);
    EXPECT_EQ(maxAbsDiff(culled.normal, all.normal), 0.0);
    EXPECT_EQ(maxAbsDiff(culled.ao, all.ao), 0.0);
}

TEST_F(Skips, FrustumTestKeepsWhatTouchesTheViewInEveryLens) {
    // A unit box in front of the camera is kept, one behind it, beside it or past the far plane is
    // culled: in both depth mappings and both projections.
    for (Projection p : {Projection::Perspective, Projection::Orthographic})
        for (DepthMode d : {DepthMode::Standard, DepthMode::Reversed}) {
            Camera c;
            c.eye = {0, 0, 0}, c.target = {0, 0, -1}, c.nearZ = 0.5f, c.farZ = 50.0f;
            c.projectionKind = p, c.depth = d;
            const glm::mat4 vp = c.projection(1.0f) * c.view();
            auto box = [](glm::vec3 centre) {
                Bounds b;
                b.add(centre - glm::vec3(0.5f));
                b.add(centre + glm::vec3(0.5f));
                return b;
            };
            const bool z01 = d == DepthMode::Reversed;
            const std::string what = std::string(projectionName(p)) + " " + depthModeName(d);
            EXPECT_FALSE(outsideFrustum(box({0, 0, -10}), vp, z01)) << what;
            EXPECT_FALSE(outsideFrustum(box({0, 0, -50}), vp, z01)) << what; // straddles far
            EXPECT_TRUE(outsideFrustum(box({0, 0, 10}), vp, z01)) << what;   // behind
            EXPECT_TRUE(outsideFrustum(box({0, 0, -60}), vp, z01)) << what;  // past far
            EXPECT_TRUE(outsideFrustum(box({500, 0, -10}), vp, z01)) << what; // beside
        }
}

TEST_F(Skips, TargetsAndPassesNothingWantsAreSkippedAndComeBackWhenWanted) {
    const Scene scene = loadScene("builtin:showcase");
    Settings s = defaultSettings();
    s.denoise.kind = DenoiseKind::Box4; // reads no normals (the bilateral does)
    auto r = makeRenderer(scene, s, 160, 90);
    r->render();
    const Image aoAll = readBack(r->texture("ao.denoised"), 1);
    const Image albedo = readBack(r->texture("gbuffer.albedo"), 3);
    // Only the AO is wanted (what `bench` judges): no composite, no albedo target.
    r->setWanted(std::set<std::string>{"ao.denoised"});
    r->invalidate();
    const FrameReport f = r->render();
    EXPECT_EQ(ranSet(f), (std::set<std::string>{"gbuffer", "ao", "denoise"}));
    bool compositeCulled = false;
    for (const auto& p : f.passes)
        compositeCulled = compositeCulled || (p.name == "composite" && p.culled);
    EXPECT_TRUE(compositeCulled);
    std::map<std::string, double> c;
    for (const auto& [k, v] : r->graph().pass("gbuffer")->counters())
        c[k] = v;
    EXPECT_EQ(c["targets_written"], 3.0); // position, normal, linear depth
    EXPECT_EQ(maxAbsDiff(readBack(r->texture("ao.denoised"), 1), aoAll), 0.0);
    // Normals from depth: the normal target goes too (the box denoiser reads none).
    s.ao.normals = NormalSource::Depth;
    r->setSettings(s);
    EXPECT_FALSE(ranSet(r->render()).count("gbuffer")); // needing less is no reason to run again
    r->invalidate();
    r->render();
    for (const auto& [k, v] : r->graph().pass("gbuffer")->counters())
        c[k] = v;
    EXPECT_EQ(c["targets_written"], 2.0);
    // Wanting everything again re-runs the G-buffer for the targets it left out.
    s.ao.normals = NormalSource::GBuffer;
    r->setSettings(s);
    r->setWanted(std::nullopt);
    const FrameReport again = r->render();
    EXPECT_TRUE(ranSet(again).count("gbuffer"));
    EXPECT_TRUE(ranSet(again).count("composite"));
    EXPECT_EQ(maxAbsDiff(readBack(r->texture("gbuffer.albedo"), 3), albedo), 0.0);
    EXPECT_EQ(maxAbsDiff(readBack(r->texture("ao.denoised"), 1), aoAll), 0.0);
    // An idle frame runs nothing.
    EXPECT_TRUE(r->render().ran().empty());
}

// The app's grid shows the composite in a cell ~290 pixels wide (Renderer::setDisplayWidth): it is
// drawn at that size, and each of its pixels is the full-size composite's texel under the pixel's
// centre - what a cell painted from the full-size image showed (view.frag) - at a fraction of the
// pixels. Only the composite re-runs when the width changes; at 0 it is full size again.
TEST_F(Skips, TheCompositeIsDrawnAtTheWidthItIsShownAtAndShowsTheSameTexels) {
    const Scene scene = loadScene("builtin:showcase");
    for (const std::string preset : {"vbao-medium", "vbao-half-medium", "learnopengl"}) {
        const int w = 320, h = 180;
        auto r = makeRenderer(scene, ssaotest::preset(preset), w, h);
        r->render();
        const Image full = readBack(r->texture("composite"), 4);
        // A cell's width; 5 texels a pixel, so no pixel centre lies on a texel edge (where an ulp of
        // the interpolated coordinate picks either neighbour).
        const int shown = 64;
        r->setDisplayWidth(shown);
        EXPECT_EQ(ranSet(r->render()), (std::set<std::string>{"composite"})) << preset;
        const Image small = readBack(r->texture("composite"), 4);
        const auto [sw, sh] = displaySize(w, h, shown);
        ASSERT_EQ(small.width, sw) << preset;
        ASSERT_EQ(small.height, sh) << preset;
        EXPECT_EQ(sw, shown);
        EXPECT_EQ(sh, 36);
        // Geometry: the very texel. Sky: the gradient at the shown pixel's own centre (composite.frag),
        // within a step of 8 bits of the full-size texel's.
        const Image position = readBack(r->texture("gbuffer.position"), 4);
        size_t geometry = 0;
        for (int y = 0; y < sh; ++y) // readBack's rows run from the top: GL's row sh - 1 - y
            for (int x = 0; x < sw; ++x) {
                const int fx = int((x + 0.5) * w / sw), fy = h - 1 - int((sh - 1 - y + 0.5) * h / sh);
                const bool onGeometry = position.at(fx, fy, 3) != 0.0f;
                geometry += onGeometry;
                for (int c = 0; c < 4; ++c)
                    if (onGeometry)
                        ASSERT_EQ(small.at(x, y, c), full.at(fx, fy, c)) << preset << " at " << x << "," << y;
                    else
                        ASSERT_NEAR(small.at(x, y, c), full.at(fx, fy, c), 1.01 / 255.0) << preset << " sky";
            }
        EXPECT_GT(geometry, size_t(sw * sh / 4)) << preset;
        r->setDisplayWidth(0);
        EXPECT_EQ(ranSet(r->render()), (std::set<std::string>{"composite"})) << preset;
        const Image again = readBack(r->texture("composite"), 4);
        EXPECT_EQ(again.width, w);
        EXPECT_EQ(again.data, full.data) << preset;
        EXPECT_ANY_THROW(r->setDisplayWidth(-1));
    }
}

TEST(DisplaySize, AViewKeepsTheAspectAndNeverGrowsAnImage) {
    EXPECT_EQ(displaySize(1172, 616, 290), std::make_pair(290, 152)); // the default window's grid cell
    EXPECT_EQ(displaySize(320, 180, 0), std::make_pair(320, 180));
    EXPECT_EQ(displaySize(100, 50, 200), std::make_pair(100, 50));
    EXPECT_EQ(displaySize(4000, 1, 3), std::make_pair(3, 1)); // never 0 rows
}
