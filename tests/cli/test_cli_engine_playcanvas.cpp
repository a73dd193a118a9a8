// PlayCanvas's CameraFrame SSAO, run for real in Chromium on its own harness page
// (tools/peers/playcanvas.html): SSAO turned on with its make-peers radius R, the AO alone read back
// through the frame's own 'ssao' debug output and scored, a time for a timed job, one image per
// setting in every session; tune writes a snippet in PlayCanvas's API.
#include "engine_test_util.h"

#include "cli/headless_runner.h"
#include "engines/engine_runner.h"
#include "engines/engine_table.h"
#include "metrics/evaluate.h"
#include "reference/reference_cache.h"
#include "scene/scene.h"
#include "settings/preset.h"
#include "scene/view_fit.h"
#include "util/json_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {
// PlayCanvas 2.23.3's CameraFrame SSAO on the corner at 96x54, R = 5 % of the diagonal, 64 reference
// rays, its gamma-encoded output decoded: its make-peers settings, and twice the radius (llvmpipe,
// Chromium 156); the tolerance is well inside the difference between the two.
constexpr double kPlayCanvasRmse = 0.0866, kPlayCanvasRmse2R = 0.0748, kPlayCanvasTolerance = 0.003;
} // namespace

TEST(CliEnginePlayCanvas, RunnerRoundTripReadsTheAoAloneAtTheMakePeersSettings) {
    NEED_MODULES();
    const ssao::EngineTable t = ssao::findEngine("playcanvas-ssao");
    EXPECT_EQ(t.page, "playcanvas.html");
    const ssao::EngineTools tools = ssao::locateEngineTools(kModules, t);
    const CornerView v = cornerView("engine_playcanvas.gltf");
    const float radius = v.radius;
    const nlohmann::json& camJson = v.cameraJson;
    ssao::EngineRunner runner(tools, t, v.file, 96, 54, {{camJson, radius}});
    const std::vector<ssao::EngineResult> res =
        runner.run({{0, {}, 0}, {0, {}, 0, {{"radius", 2.0}}}, {0, {}, 2}, {0, {{"intensity", 0.0}}, 0}, {0, {{"intensity", 4.0}}, 0}});
    ASSERT_EQ(res.size(), 5u);
    EXPECT_FLOAT_EQ(float(res[0].values.at("radius")), radius); // lengths from R
    EXPECT_EQ(res[0].values.at("intensity"), 0.5);              // the package's own
    EXPECT_EQ(res[0].values.at("samples"), 12.0);
    EXPECT_FLOAT_EQ(float(res[1].values.at("radius")), 2.0f * radius);
    EXPECT_TRUE(std::isfinite(res[2].aoMs) && std::isfinite(res[2].aoMsMin) && std::isfinite(res[2].aoMsMax));
    // What is read is the AO alone: with no intensity every pixel is 1, and with a strong one the
    // corner darkens (the package's 0.5 barely does at this size).
    long dark = 0;
    for (size_t i = 0; i < res[0].ao.data.size(); ++i) {
        EXPECT_EQ(res[3].ao.data[i], 1.0f) << "pixel " << i;
        dark += res[4].ao.data[i] < 0.97f;
        if (res[3].ao.data[i] != 1.0f) break;
    }
    EXPECT_GE(dark, 10) << "no darkening: the frame's SSAO did not run, or the scene's colour was read";
    const ssao::ReferenceImage ref = v.reference();
    const double rmse = ssao::evaluate(res[0].ao, ref).metrics.rmse, rmse2 = ssao::evaluate(res[1].ao, ref).metrics.rmse;
    std::printf("PlayCanvas CameraFrame SSAO on the corner at 96x54: RMSE %.4f (make peers), %.4f (2 R)\n", rmse, rmse2);
    EXPECT_NEAR(rmse, kPlayCanvasRmse, kPlayCanvasTolerance) << "make-peers settings on the corner at 96x54";
    EXPECT_NEAR(rmse2, kPlayCanvasRmse2R, kPlayCanvasTolerance) << "twice the radius";
    EXPECT_EQ(ssao::evaluate(res[2].ao, ref).metrics.rmse, rmse); // the timed frames draw the same AO
    // One image per setting in every session: the runner's own, which serves a second batch, and a new one.
    EXPECT_EQ(runner.run({{0, {}, 0}})[0].ao.data, res[0].ao.data);
    EXPECT_EQ(runner.sessions(), 1);
    ssao::EngineRunner fresh(tools, t, v.file, 96, 54, {{camJson, radius}});
    EXPECT_EQ(fresh.run({{0, {}, 0}})[0].ao.data, res[0].ao.data);
}

TEST(CliEnginePlayCanvas, TuneWritesASnippetInPlayCanvasApi) {
    NEED_MODULES();
    const std::string scene = writeCornerGltf("engine_tune_playcanvas.gltf");
    const std::string out = outDir("engine_tune_playcanvas") + ".json", js = outDir("engine_tune_playcanvas") + ".js";
    fs::remove(out), fs::remove(js);
    const CliRun r = ssaolab("tune --engine playcanvas-ssao --scene " + scene + " --size 96x54 --views 2 --rounds 1 --grid 3 "
                             "--knob intensity --reference-rays 8 --timing-frames 2 --save-overfit --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("tuned PlayCanvas CameraFrame SSAO on 1 views"), std::string::npos) << r.out;
    const nlohmann::json j = ssao::readJsonFile(out, "tuned");
    EXPECT_EQ(j["version"], "2.23.3");
    ASSERT_EQ(j["settings"].size(), 1u) << j.dump(1);
    EXPECT_NE(slurp(js).find("new pc.CameraFrame("), std::string::npos) << slurp(js);
    const nlohmann::json got = runSnippet("cameraFrame", slurp(js), "tuned_playcanvas");
    EXPECT_EQ(got, (nlohmann::json{{"ssao.intensity", j["settings"]["intensity"]}})) << slurp(js);
    expectCleanFailure(ssaolab("tune --engine playcanvas-ssao --scene builtin:showcase --out " + out), "glTF");
}
