// The explorer's front panel: its measurement gives bench's numbers for the same view (errors
// identical, times within their spread); in the app it fills in the background once the live
// reference is finished, a click applies a point, a shift+click compares it in Split A|B, a
// camera move cancels it and coming back finds the view's front in the cache. Waits are bounded
// loops of frames, never timings.
#include <cstdio>
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "ui_driver.h"

#include "measure/bench_run.h"
#include "measure/motion_measure.h"
#include "view/frame/front_panel.h"
#include "front/front_measurer.h"
#include "cli/headless_runner.h"
#include "reference/reference_cache.h"
#include "settings/params.h"
#include "techniques/technique.h"
#include "techniques/user/user_folder.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

using namespace ssao;
using namespace ssaotest;

namespace {
const std::string kCornell = std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf";

std::string effective(const Settings& s) {
    return toEffectiveJson(s).dump();
}
} // namespace

class FrontPanelTest : public GlTest {};

TEST_F(FrontPanelTest, MeasuresWhatBenchMeasuresOnTheSameView) {
    const int w = 160, h = 90;
    auto scene = std::make_shared<const Scene>(loadScene(kCornell));
    const float radius = 0.05f * 2.0f * scene->bounds.radius(); // bench --radius-scene 0.05
    // The view as bench sees it: its camera, clip planes fitted by a render, the cached reference.
    auto r = makeRenderer(*scene, withRadius(preset("learnopengl"), radius), w, h, defaultCamera(*scene));
    r->render();
    const Camera cam = r->camera();
    ReferenceProvider provider(*scene);
    auto ref = std::make_shared<const ReferenceImage>(provider.get(cam, w, h, {radius, 16, ReferenceVariant::Visibility}));

    const PresetStore store = PresetStore::standard(std::string(SSAOLAB_TEST_TMP) + "/front_presets");
    const std::set<std::string> wanted = {"learnopengl", "current", "gtao-low", "vbao-low", "sao-medium",
                                          "current + ao.resolution=half"};
    std::vector<Candidate> cands;
    for (auto& c : frontCandidates(defaultSettings(), store, radius))
        if (wanted.count(c.label)) cands.push_back(c);
    ASSERT_EQ(cands.size(), wanted.size());
    FrontMeasurer m(SSAOLAB_SHADER_DIR, 2, 5);
    FrontView v{scene, 1, cam, w, h, radius, ref};
    m.request(v, cands);
    for (int i = 0; i < 10000 && m.busy(); ++i)
        m.work(5.0); // slices, as between the explorer's frames
    ASSERT_FALSE(m.busy());
    ASSERT_EQ(m.points().size(), cands.size());

    // bench on the same view, size, R, rays and configurations.
    const std::string sweep = std::string(SSAOLAB_TEST_TMP) + "/front_sweep.json";
    std::ofstream(sweep) << R"({"name": "front", "groups": [{"name": "half", "set": {"ao.resolution": "half"}},
        {"name": "a", "preset": "gtao-low"}, {"name": "b", "preset": "vbao-low"}, {"name": "c", "preset": "sao-medium"}]})";
    const std::string out = std::string(SSAOLAB_TEST_TMP) + "/front_bench";
    std::filesystem::remove_all(out);
    const std::string cmd = "SSAOLAB_CACHE_DIR=" + std::string(SSAOLAB_TEST_TMP) + "/cache '" + SSAOLAB_BINARY +
                            "' bench --scene " + kCornell + " --size 160x90 --views 1 --warmup 2 --frames 5 "
                            "--reference-rays 16 --radius-scene 0.05 --no-plot --quiet --sweep " + sweep + " --out " + out;
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream in(out + "/results.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    std::map<std::string, nlohmann::json> bench; // by effective settings (the bench's R applied)
    for (size_t c = 0; c < j["configurations"].size(); ++c) {
        Settings s = defaultSettings();
        applyJson(s, j["configurations"][c]["settings"], "bench");
        bench[effective(withRadius(s, radius))] = j["results"][c];
    }
    for (const FrontPoint& p : m.points()) {
        const auto it = bench.find(effective(p.candidate.settings));
        ASSERT_NE(it, bench.end()) << p.candidate.label << " is not among bench's configurations";
        const nlohmann::json& b = it->second;
        // The same steps on the same reference: identical errors, not close ones.
        EXPECT_EQ(p.result.error.rmse, b["rmse"].get<double>()) << p.candidate.label;
        EXPECT_EQ(p.result.error.bias, b["bias"].get<double>()) << p.candidate.label;
        EXPECT_EQ(p.result.error.ssim, b["ssim"].get<double>()) << p.candidate.label;
        EXPECT_EQ(p.result.error.psnrGeometrySrgb, b["psnr_geometry_srgb"].get<double>()) << p.candidate.label;
        // Times from two runs on a machine that runs other tests at the same time (CI: 2 cores,
        // ctest -j2): the same measurement code gives the panel's median within bench's min..max
        // when the machine is quiet (the printout below); the bound is 4x either way so that load
        // alone cannot fail it - a different measurement (a wrong size, frames not timed) is off by
        // far more. Times are judged by benchmarks, not by tests.
        EXPECT_GE(p.result.gpuMs, b["gpu_ms_min"].get<double>() / 4.0) << p.candidate.label;
        EXPECT_LE(p.result.gpuMs, b["gpu_ms_max"].get<double>() * 4.0) << p.candidate.label;
        EXPECT_GT(p.result.gpuMs, 0.0);
        std::printf("%-30s panel %.3f ms, bench %.3f ms (%.3f..%.3f), RMSE %.6f both\n", p.candidate.label.c_str(),
                    p.result.gpuMs, b["gpu_ms"].get<double>(), b["gpu_ms_min"].get<double>(),
                    b["gpu_ms_max"].get<double>(), p.result.error.rmse);
    }
    // The front is consistent: no point both faster and more accurate than a front point.
    for (const auto& a : m.points())
        for (const auto& b : m.points())
            if (a.front) {
                EXPECT_FALSE(b.result.gpuMs < a.result.gpuMs && b.result.error.rmse < a.result.error.rmse)
                    << a.candidate.label << " dominated by " << b.candidate.label;
            }
}

namespace {
class FrontPanelApp : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        AppOptions o;
        o.userPresetDir = std::string(SSAOLAB_TEST_TMP) + "/front_app_presets";
        o.scene = kCornell; // a real scene
        o.renderScale = 0.15f;
        o.reference = false;
        ui_ = std::make_unique<UiDriver>(o, 1600, 900);
        app().frames().referenceRays = 8;
        app().frames().referenceOn = true;
        app().front().engines().enabled = false; // the browser's engines: test_front_engines.cpp
        ui_->settle();
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    AppCore& app() { return ui_->app(); }
    // Frames until the front of the view is measured (bounded).
    bool untilMeasured(int maxFrames = 20000) {
        for (int i = 0; i < maxFrames; ++i) {
            ui_->frame();
            const FrontMeasurer& m = app().front().measurer();
            if (m.hasView() && !m.busy() && !m.points().empty()) {
                ui_->frames(2); // the plot is drawn before the frame's slice: draw it with every point
                return true;
            }
        }
        return false;
    }
    // A widget's rect once two frames in a row draw it in the same place: a click lands on the
    // frame after the one whose rect it read (twice, under ctest -j2, the shift-click below compared
    // a point other than the one whose rect was read: B's technique was not `other`).
    ImVec4 settledRect(const std::string& key) {
        ImVec4 a = ui_->rect(key);
        for (int i = 0; i < 50; ++i) {
            ui_->frame();
            const ImVec4 b = ui_->rect(key);
            if (a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w) return b;
            a = b;
        }
        return a;
    }
    std::unique_ptr<UiDriver> ui_;
};
} // namespace

TEST_F(FrontPanelApp, FillsInTheBackgroundAndAClickAppliesAPoint) {
    EXPECT_FALSE(app().front().active) << "nothing is measured before the tab is opened";
    ui_->click("tab#Front");
    ASSERT_TRUE(untilMeasured());
    const auto& pts = app().front().points();
    // Every shipped preset, the current setting and its neighbours.
    EXPECT_GE(pts.size(), app().presets().entries().size());
    for (const auto& p : pts) {
        EXPECT_TRUE(std::isfinite(p.result.error.rmse) && p.result.error.rmse > 0 && p.result.error.rmse < 0.6)
            << p.candidate.label;
        EXPECT_GT(p.result.gpuMs, 0.0) << p.candidate.label;
        EXPECT_EQ(p.result.error.nonFinite, 0) << p.candidate.label;
    }
    const size_t cur = app().front().currentIndex(), base = app().front().measurer().baselineIndex();
    ASSERT_NE(cur, std::string::npos);
    ASSERT_NE(base, std::string::npos);
    EXPECT_EQ(pts[base].candidate.label, "learnopengl");
    EXPECT_NEAR(pts[base].timeRatio, 1.0, 1e-12);
    EXPECT_EQ(app().front().measurer().progress().fraction, 1.0);
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/ui_front.png");

    // "Cheapest at <= the current error": a button that applies it, radius kept.
    const Settings before = app().settings();
    const size_t cheap = app().front().cheapestAtMostCurrentError();
    if (cheap != std::string::npos) {
        const Candidate c = pts[cheap].candidate;
        EXPECT_LE(pts[cheap].result.error.rmse, pts[cur].result.error.rmse);
        ui_->click("front#apply_cheapest");
        EXPECT_EQ(effective(app().settings()), effective(withRadiusOf(c.settings, before)));
        EXPECT_EQ(app().settings().ao.radiusMode, before.ao.radiusMode);
    }
    // A new current setting: only it and its neighbours are measured, the presets come from the cache.
    ASSERT_TRUE(untilMeasured());
    // Shift+click on a point of another technique than the current one (the cheapest answer may
    // have made the current setting one of the presets, whose point then lies under the current's).
    const std::string other = app().settings().ao.technique == "gtao" ? "vbao" : "gtao";
    const std::string point = "front#point:" + other + "-low";
    ASSERT_TRUE(ui_->has(point));
    ImVec4 p = settledRect(point);
    ui_->clickAt((p.x + p.z) * 0.5f, (p.y + p.w) * 0.5f, false, true);
    EXPECT_EQ(app().view().mode, ViewMode::Split);
    EXPECT_EQ(app().view().splitKind, SplitKind::Candidate);
    ASSERT_TRUE(app().settingsB().has_value());
    EXPECT_EQ(app().settingsB()->ao.technique, other);
    // A plain click applies it.
    ASSERT_TRUE(untilMeasured());
    p = settledRect(point);
    ui_->clickAt((p.x + p.z) * 0.5f, (p.y + p.w) * 0.5f);
    EXPECT_EQ(app().settings().ao.technique, other);
}

TEST_F(FrontPanelApp, ACameraMoveCancelsAndComingBackFindsTheCachedFront) {
    ui_->click("tab#Front");
    ASSERT_TRUE(untilMeasured());
    const size_t n = app().front().points().size();
    const Camera home = app().cameraController().camera();
    app().cameraController().rotate(60, 0);
    app().frames().noteInteraction();
    ui_->frame();
    EXPECT_FALSE(app().front().measurer().busy());
    EXPECT_NE(app().front().waiting().find("waiting for the reference"), std::string::npos) << app().front().waiting();
    ASSERT_TRUE(untilMeasured()) << "the new view is measured in turn";
    // Back to the first view: once its reference is finished the front is there in one frame.
    app().cameraController().reset(home, app().scene().bounds.radius(), home.target);
    int frames = 0;
    while (frames++ < 20000 && !app().frames().reference().finished())
        ui_->frame();
    ui_->frame();
    EXPECT_EQ(app().front().points().size(), n);
    EXPECT_FALSE(app().front().measurer().busy()) << "measured again instead of read from the cache";
}

TEST_F(FrontPanelApp, SaysWhyAnUnfilteredPointLooksGrainy) {
    // denoise.kind=auto leaves vbao unfiltered: the tab says why and what removes the grain.
    app().settings().ao.technique = "vbao";
    app().settings().denoise.kind = DenoiseKind::Auto;
    app().settings().temporal.enabled = false;
    ui_->click("tab#Front");
    ui_->frames(2);
    EXPECT_TRUE(ui_->has("front#grain"));
    // A filtered point, or one accumulated over frames, has nothing to explain.
    app().view().widgetRects.clear();
    app().settings().temporal.enabled = true;
    ui_->frames(2);
    EXPECT_FALSE(ui_->has("front#grain"));
    app().view().widgetRects.clear();
    app().settings().temporal.enabled = false;
    app().settings().denoise.kind = DenoiseKind::Bilateral;
    ui_->frames(2);
    EXPECT_FALSE(ui_->has("front#grain"));
}

TEST_F(FrontPanelApp, TheMotionAxisScoresEveryCandidateAsBenchMotionDoes) {
    FrontPanel& f = app().front();
    f.motionPath.frames = 4;
    f.motionMaxWidth = 96, f.motionMaxHeight = 54; // the cap applies: the view is larger
    f.motionCacheDir = std::string(SSAOLAB_TEST_TMP) + "/front_motion_cache";
    std::filesystem::remove_all(f.motionCacheDir);
    ui_->click("tab#Front");
    ASSERT_TRUE(untilMeasured());
    EXPECT_TRUE(ui_->has("front#y:RMSE"));
    const size_t still = f.points().size();
    ui_->click("front#axis_motion");
    ASSERT_EQ(f.axis, FrontPanel::Axis::Motion);
    // Until every candidate has its motion score, the tab says what it waits for.
    bool said = false, done = false;
    for (int i = 0; i < 20000 && !done; ++i) {
        const bool busy = f.motion().busy();
        app().view().widgetRects.clear();
        ui_->frame();
        said |= busy && ui_->has("front#motion_progress");
        done = f.motion().hasView() && !f.motion().busy() && !f.measurer().busy() && f.points().size() == still;
    }
    ASSERT_TRUE(done) << f.points().size() << " of " << still << " scored: " << f.motion().progress().error;
    EXPECT_TRUE(said) << "no progress shown while the motion scores were not ready";
    app().view().widgetRects.clear();
    ui_->frames(2);
    EXPECT_TRUE(ui_->has("front#y:" + f.axisName()));
    EXPECT_NE(f.axisName().find("motion score"), std::string::npos);
    EXPECT_FALSE(ui_->has("front#y:RMSE"));
    for (const auto& p : f.points()) {
        ASSERT_TRUE(p.motion.has_value()) << p.candidate.label;
        EXPECT_TRUE(std::isfinite(p.score) && p.score > 0) << p.candidate.label;
        EXPECT_EQ(p.score, motionScore(*p.motion)) << p.candidate.label;
    }
    // The path as asked, at the capped size of the view's reference.
    const MotionView& v = f.motion().view();
    const auto& key = *app().frames().reference().key();
    EXPECT_EQ(v.spec.frames, 4);
    EXPECT_EQ(std::make_pair(v.width, v.height), motionSize(key.width, key.height, 96, 54));
    EXPECT_LE(v.width, 96);
    EXPECT_LE(v.height, 54);
    EXPECT_LT(v.width, key.width);
    // One candidate scored anew, outside the app: traceMotionTruth (no cache) and measureMotion.
    const size_t cur = f.currentIndex();
    ASSERT_NE(cur, std::string::npos);
    const FrontPoint& c = f.points()[cur];
    ReferenceProvider provider(*v.scene, "");
    const MotionTruth truth = traceMotionTruth(provider, v.scene->bounds, key.camera, v.width, v.height,
                                               f.motionPath, v.settings);
    Renderer r(SSAOLAB_SHADER_DIR);
    r.setWanted(std::set<std::string>{"ao.denoised"});
    r.setSize(v.width, v.height);
    r.setScene(*v.scene);
    const MotionMetrics m = measureMotion(r, c.candidate.settings, truth);
    EXPECT_NEAR(c.score, motionScore(m), 1e-9 * motionScore(m));
    EXPECT_NEAR(c.motion->rmseMean, m.rmseMean, 1e-9);
    EXPECT_NEAR(c.motion->instability, m.instability, 1e-9);
    EXPECT_EQ(c.motion->pairs, m.pairs);
    std::printf("current: motion score %.6f (app) %.6f (measureMotion), still RMSE %.6f, %dx%d, %zu candidates\n",
                c.score, motionScore(m), c.result.error.rmse, v.width, v.height, f.points().size());
    // The answers are on the motion axis.
    const size_t cheap = f.cheapestAtMostCurrentError();
    if (cheap != std::string::npos) {
        EXPECT_LE(f.points()[cheap].score, c.score);
    }
    // Back to still: the y axis is the RMSE again.
    ui_->click("front#axis_still");
    app().view().widgetRects.clear();
    ui_->frames(2);
    EXPECT_TRUE(ui_->has("front#y:RMSE"));
    EXPECT_EQ(f.points().size(), still);
    // On the motion axis, a camera move cancels as it does the still front.
    ui_->click("front#axis_motion");
    ui_->frame();
    EXPECT_TRUE(f.motion().hasView());
    app().cameraController().rotate(60, 0);
    app().frames().noteInteraction();
    ui_->frame();
    EXPECT_FALSE(f.motion().hasView());
    EXPECT_TRUE(f.points().empty());
    EXPECT_NE(f.waiting().find("waiting for the reference"), std::string::npos) << f.waiting();
}

TEST(FrontCandidates, EachUserTechniqueIsAPointAtItsHeadersDefaults) {
    const std::string path = std::string(SSAOLAB_SOURCE_DIR) + "/examples/techniques/xegtao.ao.glsl";
    setUserTechniques({readUserTechnique(path)});
    const PresetStore store = PresetStore::standard(std::string(SSAOLAB_TEST_TMP) + "/front_presets");
    Settings current = defaultSettings();
    setParam(current, "ao.resolution", "half"); // the current settings' other choices carry over
    bool found = false;
    for (const Candidate& c : frontCandidates(current, store, 0.5f)) {
        if (c.label != "user.xegtao") continue;
        found = true;
        EXPECT_EQ(c.origin, "user technique");
        EXPECT_EQ(c.settings.ao.technique, "user.xegtao");
        EXPECT_EQ(c.settings.ao.resolution, AoResolution::Half);
        EXPECT_EQ(findParam("user.xegtao.slices")->get(c.settings), 3.0); // the header's default
    }
    EXPECT_TRUE(found);
    setUserTechniques({});
}

TEST(FrontCandidates, ATechniqueThatReadsTheSecondLayerIsTriedWithIt) {
    const PresetStore store = PresetStore::standard(std::string(SSAOLAB_TEST_TMP) + "/front_presets");
    auto has = [&](const Settings& current) {
        for (const Candidate& c : frontCandidates(current, store, 0.5f))
            if (c.label == "current + gbuffer.second_layer=true") return c.settings.gbuffer.secondLayer;
        return false;
    };
    Settings bitmask = defaultSettings();
    setParam(bitmask, "ao.technique", "vbao");
    EXPECT_TRUE(has(bitmask));
    EXPECT_FALSE(has(defaultSettings())); // the kernel reads no second layer
}
