// The Front tab's web engines: the panel scores an engine exactly as `bench --engines` does on the
// same view (the same runner and reference: identical errors, for the defaults and a tune result);
// in the app an engine point joins the front, shows its AO frame in
// Split B and copies its settings as JavaScript; missing packages are one line and no engine
// point, the rest of the tab unchanged; a built-in scene is one line. Waits are bounded loops.
#include "gl_fixture.h"
#include "scene/load/load_scene.h"
#include "ui_driver.h"

#include "measure/bench_run.h"
#include "engines/engine_runner.h"
#include "engines/engine_table.h"
#include "engines/engine_snippet.h"
#include "front/engine_front.h"
#include "cli/headless_runner.h"
#include "metrics/evaluate.h"
#include "reference/reference_cache.h"
#include "settings/preset.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

using namespace ssao;
using namespace ssaotest;
namespace fs = std::filesystem;

namespace {
const std::string kCornell = std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf";
const std::string kModules = defaultEngineModules(); // the build folder's peers/node_modules

#define NEED_MODULES()                                                                                              \
    ASSERT_TRUE(fs::is_regular_file(kModules + "/n8ao/package.json") &&                                           \
                fs::is_regular_file(kModules + "/playwright-core/package.json"))                                  \
        << "the pinned npm packages are not installed in " << kModules << " (make engine-modules)"

// Polls until the engines are done (bounded: a browser session takes seconds, not minutes).
bool untilDone(EngineFront& e, const std::function<void()>& step) {
    for (int i = 0; i < 12000; ++i) {
        step();
        e.poll();
        if (!e.busy()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20)); // the browser's CPU, not ours
    }
    return false;
}

std::string tunedDir(const std::string& name) {
    const fs::path dir = fs::path(SSAOLAB_TEST_TMP) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}
} // namespace

class FrontEnginesGl : public GlTest {};

TEST_F(FrontEnginesGl, ScoresWhatBenchEnginesScoresOnTheSameView) {
    NEED_MODULES();
    const int w = 160, h = 90;
    auto scene = std::make_shared<const Scene>(loadNamedScene(kCornell));
    const float radius = 0.05f * 2.0f * scene->bounds.radius(); // bench --radius-scene 0.05
    // The view as bench sees it: its camera, clip planes fitted by a render, the reference of 16 rays.
    auto r = makeRenderer(*scene, withRadius(preset("learnopengl"), radius), w, h, defaultCamera(*scene));
    r->render();
    const Camera cam = r->camera();
    ReferenceProvider provider(*scene, std::string(SSAOLAB_TEST_TMP) + "/cache");
    auto ref = std::make_shared<const ReferenceImage>(provider.get(cam, w, h, {radius, 16, ReferenceVariant::Visibility}));
    // A tune result as `tune --engine --out` writes one: aoRadius 1.5 x its make-peers value (R),
    // intensity the engine's own value, the cost settings it chose.
    const std::string dir = tunedDir("front_engines_tuned"), tuned = dir + "/n8ao-test.json";
    std::ofstream(tuned) << R"({"engine": "n8ao", "version": "2.1.0", "settings": {"aoRadius": 9, "intensity": 3},
        "search": {"aoRadius": {"x_make_peers_value": 1.5}, "intensity": {"value": 3}},
        "cost_settings": {"values": {"aoSamples": 8}}})";
    std::ofstream(dir + "/notes.json") << R"({"what": "not a tune result"})";

    EngineFront e;
    e.engines = {"n8ao"};
    e.frames = 2;
    e.request({scene, 1, cam, w, h, radius, ref}, kCornell, dir);
    ASSERT_TRUE(untilDone(e, [] {}));
    ASSERT_FALSE(e.off()) << e.status();
    ASSERT_TRUE(e.errors().empty()) << e.errors()[0];
    ASSERT_EQ(e.tunedErrors().size(), 1u); // notes.json: one line naming it, the rest measured
    EXPECT_NE(e.tunedErrors()[0].find("notes.json: not a `ssaolab tune --engine --out` file"), std::string::npos)
        << e.tunedErrors()[0];
    const auto defaults = e.sample("N8AO defaults"), fit = e.sample("N8AO tuned (n8ao-test)");
    const auto shipped = e.sample("N8AO as shipped");
    ASSERT_TRUE(defaults && fit && shipped);
    // A point needs a time above zero on the log axis (engine_front.cpp); at 160x90 a pass can time at
    // or below the browser's clock under load, and then it is measured but has no point.
    EXPECT_EQ(e.points().size(), size_t(defaults->aoMs > 0) + size_t(fit->aoMs > 0) + size_t(shipped->aoMs > 0));
    EXPECT_FLOAT_EQ(float(defaults->values.at("aoRadius")), radius); // make peers: the radius is R
    EXPECT_EQ(shipped->values.at("aoRadius"), 5.0);                   // the package's own, whatever R
    EXPECT_EQ(fit->values.at("aoRadius"), defaults->values.at("aoRadius") * 1.5);
    EXPECT_EQ(fit->values.at("intensity"), 3.0);
    EXPECT_EQ(fit->values.at("aoSamples"), 8.0);

    // bench --engines on the same view, size, R and rays, with the same tune result.
    const std::string sweep = std::string(SSAOLAB_TEST_TMP) + "/front_engines_sweep.json";
    std::ofstream(sweep) << R"({"name": "front", "groups": [{"name": "a", "preset": "gtao-low"}]})";
    const std::string out = std::string(SSAOLAB_TEST_TMP) + "/front_engines_bench";
    fs::remove_all(out);
    const std::string cmd = "SSAOLAB_CACHE_DIR=" + std::string(SSAOLAB_TEST_TMP) + "/cache '" + SSAOLAB_BINARY +
                            "' bench --scene " + kCornell + " --size 160x90 --views 1 --warmup 0 --frames 2 "
                            "--reference-rays 16 --radius-scene 0.05 --no-plot --quiet --sweep " + sweep +
                            " --engines n8ao --engine-settings " + tuned + " --engine-modules " + kModules + " --out " + out;
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream in(out + "/results.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    std::map<std::string, nlohmann::json> bench;
    for (const auto& row : j["results"])
        bench[row["label"].get<std::string>()] = row;
    for (const auto& [panel, label] : {std::make_pair(defaults, "engine n8ao (defaults)"), std::make_pair(fit, "engine n8ao (tuned)")}) {
        ASSERT_TRUE(bench.count(label)) << label << " is not among bench's rows";
        const nlohmann::json& b = bench[label];
        // The same AO on the same reference: identical errors, not close ones.
        EXPECT_EQ(panel->error.rmse, b["rmse"].get<double>()) << label;
        EXPECT_EQ(panel->error.bias, b["bias"].get<double>()) << label;
        EXPECT_EQ(panel->error.ssim, b["ssim"].get<double>()) << label;
        EXPECT_EQ(panel->error.rmseEdge, b["rmse_edge"].get<double>()) << label;
        EXPECT_TRUE(std::isfinite(panel->aoMs)) << label << ": timed in the browser";
        std::printf("%-26s RMSE %.6f (panel) %.6f (bench), AO %.2f ms (panel) %.2f ms (bench)\n",
                    panel->candidate.label.c_str(), panel->error.rmse, b["rmse"].get<double>(), panel->aoMs,
                    b["gpu_ms"].get<double>());
    }
    // The snippet sets what it ran with, in the engine's API.
    const EngineTable t = findEngine("n8ao");
    EXPECT_NE(fit->snippet.find("n8aopass.configuration.aoRadius = " + jsValue(*t.find("aoRadius"), fit->values.at("aoRadius")) + ";"),
              std::string::npos)
        << fit->snippet;
    EXPECT_NE(fit->snippet.find("n8aopass.configuration.intensity = 3;"), std::string::npos) << fit->snippet;
    EXPECT_NE(fit->snippet.find("n8aopass.configuration.aoSamples = 8;"), std::string::npos) << fit->snippet;
}

TEST(FrontEngines, ABuiltInSceneIsOneLineAndNoJob) {
    auto scene = std::make_shared<const Scene>(loadScene("builtin:corner"));
    auto ref = std::make_shared<const ReferenceImage>();
    EngineFront e;
    e.request({scene, 1, defaultCamera(*scene), 64, 36, 0.1f, ref}, "builtin:corner", tunedDir("front_engines_none"));
    EXPECT_FALSE(e.busy());
    EXPECT_EQ(e.status(), "engines load glTF files; this scene is built in");
    EXPECT_TRUE(e.points().empty());
}

namespace {
class FrontEnginesApp : public GlTest {
  protected:
    void open(const std::string& modules) {
        AppOptions o;
        o.userPresetDir = tunedDir("front_engines_presets"); // its engines/ holds no tune result
        o.scene = kCornell;
        o.renderScale = 0.15f;
        o.reference = false;
        o.engineModules = modules;
        ui_ = std::make_unique<UiDriver>(o, 1600, 900);
        app().frames().referenceRays = 8;
        app().frames().referenceOn = true;
        app().front().engines().engines = {"n8ao"};
        app().front().engines().frames = 2;
        ui_->settle();
        ui_->click("tab#Front");
    }
    void TearDown() override {
        ui_.reset();
        GlTest::TearDown();
    }
    AppCore& app() { return ui_->app(); }
    // Frames until ssaolab's candidates are measured and the engines are done or off (bounded).
    bool untilEngines() {
        for (int i = 0; i < 40000; ++i) {
            ui_->frame();
            const FrontPanel& f = app().front();
            const bool measured = f.measurer().hasView() && !f.measurer().busy() && !f.points().empty();
            if (measured && !f.engines().busy() && (f.engines().off() || !f.engines().samples().empty())) {
                ui_->frames(2); // the tab drawn with every point
                return true;
            }
            if (measured) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    }
    std::unique_ptr<UiDriver> ui_;
};
} // namespace

TEST_F(FrontEnginesApp, AnEnginePointJoinsTheFrontShowsItsFrameInSplitBAndCopiesItsSnippet) {
    NEED_MODULES();
    open("");
    ASSERT_TRUE(untilEngines());
    const EngineFront& e = app().front().engines();
    ASSERT_FALSE(e.off()) << e.status();
    const std::string label = "N8AO defaults";
    const auto sample = e.sample(label);
    ASSERT_TRUE(sample) << e.status();
    size_t engine = std::string::npos;
    for (size_t i = 0; i < app().front().points().size(); ++i)
        if (app().front().points()[i].candidate.label == label) engine = i;
    ASSERT_NE(engine, std::string::npos) << "the engine's point is not on the Front tab's plot";
    const FrontPoint& p = app().front().points()[engine];
    EXPECT_TRUE(p.candidate.isEngine());
    EXPECT_EQ(p.result.error.rmse, sample->error.rmse);
    EXPECT_EQ(p.result.gpuMs, sample->aoMs);
    EXPECT_TRUE(ui_->has("front#point:" + label));
    // The view the engine ran is the reference's: its size, and the live reference's errors.
    const auto& key = *app().frames().reference().key();
    EXPECT_EQ(sample->ao.width, key.width);
    EXPECT_EQ(sample->ao.height, key.height);
    EXPECT_EQ(sample->error.rmse, evaluate(sample->ao, *app().frames().reference().finished()).metrics.rmse);
    // The answers stay among settings that can be applied.
    for (size_t a : {app().front().cheapestAtMostCurrentError(), app().front().mostAccurateWithinCurrentTime()})
        if (a != std::string::npos) {
            EXPECT_FALSE(app().front().points()[a].candidate.isEngine());
        }

    // A|B: B is the engine's AO frame, an image; no chain B is rendered.
    ui_->click("front#engine_compare:" + label);
    ui_->frames(2);
    EXPECT_TRUE(app().view().imageB());
    EXPECT_EQ(app().view().splitCandidateB, label);
    EXPECT_EQ(app().view().splitBuffer, "ao.denoised");
    EXPECT_FALSE(app().settingsB().has_value());
    EXPECT_TRUE(ui_->has("split#image_b"));
    std::string why;
    EXPECT_NE(app().splitImageB(why), nullptr) << why;
    ui_->save(std::string(SSAOLAB_TEST_TMP) + "/ui_front_engine_split.png");

    // copy snippet: the settings it ran with, as JavaScript, on the clipboard.
    ui_->click("front#engine_snippet:" + label);
    const char* clip = ImGui::GetClipboardText();
    ASSERT_NE(clip, nullptr);
    EXPECT_EQ(std::string(clip), sample->snippet);
    EXPECT_NE(sample->snippet.find("n8aopass.configuration.aoRadius = "), std::string::npos) << sample->snippet;
    EXPECT_NE(app().status().find("copied the settings of " + label), std::string::npos) << app().status();
}

TEST_F(FrontEnginesApp, MissingPackagesAreOneLineNoEnginePointAndTheRestUnchanged) {
    const std::string empty = tunedDir("front_engines_no_modules");
    open(empty);
    ASSERT_TRUE(untilEngines());
    const FrontPanel& f = app().front();
    ASSERT_TRUE(f.engines().off());
    const std::string line = f.engines().status();
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
    EXPECT_EQ(line.rfind("engines are off: ", 0), 0u) << line;
    EXPECT_NE(line.find("is not installed in " + empty), std::string::npos) << line;
    EXPECT_NE(line.find("make engine-modules"), std::string::npos) << line;
    EXPECT_TRUE(ui_->has("front#engines"));
    EXPECT_FALSE(ui_->has("front#engine_snippet:N8AO defaults"));
    for (const FrontPoint& p : f.points())
        EXPECT_FALSE(p.candidate.isEngine()) << p.candidate.label;
    // ssaolab's own candidates are measured as always.
    EXPECT_GE(f.points().size(), app().presets().entries().size());
    EXPECT_NE(f.currentIndex(), std::string::npos);
    EXPECT_NE(f.baselineIndex(), std::string::npos);
    // Off stays off: nothing is started again for the next view.
    app().cameraController().rotate(40, 0);
    app().frames().noteInteraction();
    ASSERT_TRUE(untilEngines());
    EXPECT_TRUE(f.engines().off());
    EXPECT_EQ(f.engines().status(), line);
}
