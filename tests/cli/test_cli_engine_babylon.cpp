// Babylon.js's SSAO2RenderingPipeline and SSAORenderingPipeline, run for real in Chromium on their
// harness page (tools/peers/babylon.html): make-peers settings from R, the AO alone read back and
// scored, a time for a timed job, one image per setting in every session; tune writes a snippet in
// Babylon's API; bench --engines runs both beside a three.js engine, one session per page.
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

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {
// SSAO2RenderingPipeline 9.28.0 on the corner at 96x54, R = 5 % of the diagonal, 64 reference rays:
// its make-peers settings, and twice the radius (llvmpipe, Chromium 156); the tolerance is well
// inside the difference between the two.
constexpr double kBabylonRmse = 0.0898, kBabylonRmse2R = 0.0774, kBabylonTolerance = 0.003;
// SSAORenderingPipeline 9.28.0 on the same corner, the same way: make peers, and as shipped (its
// radius 0.0001 of the screen and base 0.5: hardly any occlusion, and never below 0.5).
constexpr double kSsaoRmse = 0.0905, kSsaoShippedRmse = 0.0912;
} // namespace

TEST(CliEngineBabylon, RunnerRoundTripReadsTheAoAloneAtTheMakePeersSettings) {
    NEED_MODULES();
    const ssao::EngineTable t = ssao::findEngine("babylon-ssao2");
    EXPECT_EQ(t.page, "babylon.html");
    const ssao::EngineTools tools = ssao::locateEngineTools(kModules, t);
    const CornerView v = cornerView("engine_babylon.gltf");
    const float radius = v.radius;
    const nlohmann::json& camJson = v.cameraJson;
    ssao::EngineRunner runner(tools, t, v.file, 96, 54, {{camJson, radius}});
    const std::vector<ssao::EngineResult> res =
        runner.run({{0, {}, 0}, {0, {}, 0, {{"radius", 2.0}}}, {0, {}, 2}, {0, {{"totalStrength", 0.0}}, 0}});
    ASSERT_EQ(res.size(), 4u);
    EXPECT_FLOAT_EQ(float(res[0].values.at("radius")), radius);               // lengths from R
    EXPECT_FLOAT_EQ(float(res[0].values.at("epsilon")), 0.01f * radius);      // at the defaults' ratio
    EXPECT_FLOAT_EQ(float(res[0].values.at("maxZ")), camJson["far"].get<float>() / 0.75f); // no fade inside the scene
    EXPECT_EQ(res[0].values.at("samples"), 8.0);                               // the package's own
    EXPECT_FLOAT_EQ(float(res[1].values.at("radius")), 2.0f * radius);
    EXPECT_TRUE(std::isfinite(res[2].aoMs) && std::isfinite(res[2].aoMsMin) && std::isfinite(res[2].aoMsMax));
    const ssao::ReferenceImage ref = v.reference();
    // What is read is the AO alone: with no strength every pixel is 1 (the white scene, unlit), and
    // at the make-peers settings the corner darkens (the pipeline's shaders were ready).
    long dark = 0;
    for (size_t i = 0; i < res[0].ao.data.size(); ++i) {
        EXPECT_EQ(res[3].ao.data[i], 1.0f) << "pixel " << i;
        dark += res[0].ao.data[i] < 0.97f;
        if (res[3].ao.data[i] != 1.0f) break;
    }
    EXPECT_GE(dark, 10) << "no darkening: the pipeline's shaders were not ready, or the scene's colour was read";
    const double rmse = ssao::evaluate(res[0].ao, ref).metrics.rmse, rmse2 = ssao::evaluate(res[1].ao, ref).metrics.rmse;
    std::printf("SSAO2RenderingPipeline on the corner at 96x54: RMSE %.4f (make peers), %.4f (2 R)\n", rmse, rmse2);
    EXPECT_NEAR(rmse, kBabylonRmse, kBabylonTolerance) << "make-peers settings on the corner at 96x54";
    EXPECT_NEAR(rmse2, kBabylonRmse2R, kBabylonTolerance) << "twice the radius";
    EXPECT_EQ(ssao::evaluate(res[2].ao, ref).metrics.rmse, rmse); // the timed frames draw the same AO
    // One image per setting in every session: the pipeline's noise is seeded. The runner's own
    // session serves a second batch (the pipeline it built stays), a new runner starts a new browser.
    EXPECT_EQ(runner.run({{0, {}, 0}})[0].ao.data, res[0].ao.data);
    EXPECT_EQ(runner.sessions(), 1);
    ssao::EngineRunner fresh(tools, t, v.file, 96, 54, {{camJson, radius}});
    EXPECT_EQ(fresh.run({{0, {}, 0}})[0].ao.data, res[0].ao.data);
}

TEST(CliEngineBabylon, TheOlderPipelineRunsWithItsLengthsInTheDepthRenderersRange) {
    NEED_MODULES();
    const ssao::EngineTable t = ssao::findEngine("babylon-ssao");
    EXPECT_EQ(t.page, "babylon.html");
    const CornerView v = cornerView("engine_babylon_ssao.gltf");
    const nlohmann::json& cam = v.cameraJson;
    ssao::EngineRunner runner(ssao::locateEngineTools(kModules, t), t, v.file, 96, 54, {{cam, v.radius}});
    const std::vector<ssao::EngineResult> res =
        runner.run({{0, {}, 0}, {0, ssao::shippedValues(t), 0}, {0, {{"totalStrength", 0.0}}, 0}, {0, {}, 2}, {0, {{"base", 0.0}}, 0}});
    ASSERT_EQ(res.size(), 5u);
    // Its lengths are fractions of far - near: R projected onto the screen at the camera's target
    // (the shader divides by (z - near) / (far - near)), and R as a depth difference.
    const double near = cam["near"].get<double>(), span = cam["far"].get<double>() - near;
    const double tanHalf = std::tan(cam["fov_y_deg"].get<double>() * M_PI / 360);
    double zt = 0;
    for (int i = 0; i < 3; ++i) zt += std::pow(cam["target"][i].get<double>() - cam["eye"][i].get<double>(), 2);
    zt = std::sqrt(zt);
    EXPECT_NEAR(res[0].values.at("radius"), v.radius / (2 * tanHalf * zt) * (zt - near) / span, 1e-6 * res[0].values.at("radius"));
    EXPECT_NEAR(res[0].values.at("area"), v.radius / span, 1e-6 * res[0].values.at("area"));
    EXPECT_NEAR(res[0].values.at("fallOff"), res[0].values.at("area") * 1e-6 / 0.0075, 1e-6 * res[0].values.at("fallOff"));
    EXPECT_EQ(res[1].values.at("radius"), 0.0001); // as shipped: the package's own values
    EXPECT_EQ(res[1].values.at("base"), 0.5);
    const ssao::ReferenceImage ref = v.reference();
    long dark = 0;
    for (size_t i = 0; i < res[0].ao.data.size(); ++i) {
        ASSERT_EQ(res[2].ao.data[i], 1.0f) << "no strength: the AO alone is 1 (pixel " << i << ")";
        ASSERT_GE(res[1].ao.data[i], 0.5f) << "as shipped, its base keeps the AO at or above 0.5 (pixel " << i << ")";
        dark += res[4].ao.data[i] < 0.9f;
    }
    EXPECT_GE(dark, 10) << "no darkening at the make-peers settings with no base";
    const double rmse = ssao::evaluate(res[0].ao, ref).metrics.rmse, shipped = ssao::evaluate(res[1].ao, ref).metrics.rmse;
    std::printf("SSAORenderingPipeline on the corner at 96x54: RMSE %.4f (make peers), %.4f (as shipped)\n", rmse, shipped);
    EXPECT_NEAR(rmse, kSsaoRmse, kBabylonTolerance) << "make-peers settings on the corner at 96x54";
    EXPECT_NEAR(shipped, kSsaoShippedRmse, kBabylonTolerance) << "as shipped";
    EXPECT_TRUE(std::isfinite(res[3].aoMs));
    EXPECT_EQ(ssao::evaluate(res[3].ao, ref).metrics.rmse, rmse); // the timed frames draw the same AO
    EXPECT_EQ(runner.run({{0, {}, 0}})[0].ao.data, res[0].ao.data); // seeded: the same image every session
}

TEST(CliEngineBabylon, TuneWritesASnippetInBabylonsApi) {
    NEED_MODULES();
    const std::string scene = writeCornerGltf("engine_tune_babylon.gltf");
    const std::string out = outDir("engine_tune_babylon") + ".json", js = outDir("engine_tune_babylon") + ".js";
    fs::remove(out), fs::remove(js);
    const CliRun r = ssaolab("tune --engine babylon-ssao2 --scene " + scene + " --size 96x54 --views 2 --rounds 1 --grid 3 "
                             "--knob totalStrength --reference-rays 8 --timing-frames 2 --save-overfit --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("tuned Babylon.js SSAO2RenderingPipeline on 1 views"), std::string::npos) << r.out;
    const nlohmann::json j = ssao::readJsonFile(out, "tuned");
    EXPECT_EQ(j["version"], "9.28.0");
    ASSERT_EQ(j["settings"].size(), 1u) << j.dump(1);
    EXPECT_NE(slurp(js).find("new BABYLON.SSAO2RenderingPipeline("), std::string::npos) << slurp(js);
    const nlohmann::json got = runSnippet("ssao", slurp(js), "tuned_babylon");
    EXPECT_EQ(got, (nlohmann::json{{"totalStrength", j["settings"]["totalStrength"]}})) << slurp(js);
    // A builtin scene: refused before the browser starts.
    expectCleanFailure(ssaolab("tune --engine babylon-ssao2 --scene builtin:showcase --out " + out), "glTF");
    // The older pipeline: its snippet constructs it and sets what was fitted.
    fs::remove(out), fs::remove(js);
    const CliRun old = ssaolab("tune --engine babylon-ssao --scene " + scene + " --size 96x54 --views 2 --rounds 1 --grid 3 "
                               "--knob base --reference-rays 8 --timing-frames 2 --save-overfit --out " + out);
    ASSERT_EQ(old.exitCode, 0) << old.out << old.err;
    const nlohmann::json jo = ssao::readJsonFile(out, "tuned");
    EXPECT_NE(slurp(js).find("new BABYLON.SSAORenderingPipeline("), std::string::npos) << slurp(js);
    EXPECT_EQ(runSnippet("ssao", slurp(js), "tuned_babylon_ssao"), (nlohmann::json{{"base", jo["settings"]["base"]}})) << slurp(js);
    expectCleanFailure(ssaolab("tune --engine babylon-ssao --scene builtin:showcase --out " + out), "glTF");
}

// Three harness pages in one bench: the three.js engine, Babylon's two pipelines and Filament run
// in one session a page, and every row is scored against the same reference.
TEST(CliEngineBabylon, BenchRunsEnginesOfTwoPagesBesideEachOther) {
    NEED_MODULES();
    const std::string scene = writeCornerGltf("bench_babylon.gltf"), out = outDir("bench_babylon");
    fs::remove_all(out);
    const std::string sweep = writeTemp("bench_babylon_sweep.json", R"({"name": "b", "groups": [{"name": "g", "set": {"ao.technique": "gtao"}}]})");
    const CliRun r = ssaolab("bench --scene " + scene + " --size 96x54 --views 1 --frames 2 --warmup 0 --reference-rays 8 "
                             "--no-plot --quiet --engines n8ao,babylon-ssao2,babylon-ssao,filament-ssao --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(out + "/results.json"));
    int rows = 0;
    for (const auto& v : j["results"]) {
        const std::string label = j["configurations"][v["config"].get<size_t>()]["label"];
        if (label.rfind("engine ", 0) != 0) continue;
        ++rows;
        EXPECT_TRUE(v["rmse"].is_number()) << label;
        EXPECT_LE(v["rmse"].get<double>(), 1.0) << label;
    }
    EXPECT_EQ(rows, 8) << "n8ao, babylon-ssao2, babylon-ssao and filament-ssao, each as make peers and as shipped";
    expectCleanFailure(ssaolab("bench --scene " + scene + " --engines Babylon-SSAO2 --out " + out + "_x"),
                       "did you mean babylon-ssao2");
}
