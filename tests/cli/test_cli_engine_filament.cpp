// Filament's web build, run for real in Chromium on its own harness page (tools/peers/filament.html):
// its View's ambient occlusion at the make-peers settings from R, the AO alone isolated (the frame
// with the AO over the same frame without, the scene lit by a uniform environment alone) and
// scored, a time for a timed job, one image per setting in every session; tune writes a snippet in
// Filament's API that turns the AO on.
#include "engine_test_util.h"

#include "engines/engine_runner.h"
#include "engines/engine_table.h"
#include "metrics/evaluate.h"
#include "util/json_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

using namespace ssaotest;
namespace fs = std::filesystem;

namespace {
// Filament 1.53.4's AO on the corner at 96x54, R = 5 % of the diagonal, 64 reference rays: its
// make-peers settings, and twice the radius (llvmpipe, Chromium 156); the tolerance is well inside
// the difference between the two.
constexpr double kFilamentRmse = 0.1001, kFilamentRmse2R = 0.2398, kFilamentTolerance = 0.003;
} // namespace

TEST(CliEngineFilament, RunnerRoundTripIsolatesTheAoAtTheMakePeersSettings) {
    NEED_MODULES();
    const ssao::EngineTable t = ssao::findEngine("filament-ssao");
    EXPECT_EQ(t.page, "filament.html");
    const CornerView v = cornerView("engine_filament.gltf");
    ssao::EngineRunner runner(ssao::locateEngineTools(kModules, t), t, v.file, 96, 54, {{v.cameraJson, v.radius}});
    const std::vector<ssao::EngineResult> res =
        runner.run({{0, {}, 0}, {0, {}, 0, {{"radius", 2.0}}}, {0, {}, 2}, {0, {{"intensity", 0.0}}, 0}, {0, ssao::shippedValues(t), 0}});
    ASSERT_EQ(res.size(), 5u);
    EXPECT_FLOAT_EQ(float(res[0].values.at("radius")), v.radius); // lengths from R, at the defaults' ratios
    EXPECT_FLOAT_EQ(float(res[0].values.at("bias")), float(v.radius * 0.0005 / 0.3));
    EXPECT_FLOAT_EQ(float(res[0].values.at("bilateralThreshold")), float(v.radius * 0.05 / 0.3));
    EXPECT_EQ(res[0].values.at("quality"), 0.0); // the package's own
    EXPECT_EQ(res[0].values.at("resolution"), 0.5);
    EXPECT_FLOAT_EQ(float(res[1].values.at("radius")), 2.0f * v.radius);
    EXPECT_EQ(res[4].values.at("radius"), 0.3); // as shipped: 0.3 m whatever the scene
    EXPECT_TRUE(std::isfinite(res[2].aoMs) && std::isfinite(res[2].aoMsMin) && std::isfinite(res[2].aoMsMax));
    // The AO alone: with no intensity the frame with the AO is the frame without it (to the canvas's
    // 8 bits), and at the make-peers settings the corner darkens.
    long dark = 0;
    for (size_t i = 0; i < res[0].ao.data.size(); ++i) {
        ASSERT_GE(res[3].ao.data[i], 0.99f) << "no intensity: the ratio of two equal frames (pixel " << i << ")";
        ASSERT_LE(res[0].ao.data[i], 1.0f);
        dark += res[0].ao.data[i] < 0.9f;
    }
    EXPECT_GE(dark, 10) << "no darkening: the AO did not run, or the lighting it darkens was not isolated";
    const ssao::ReferenceImage ref = v.reference();
    const double rmse = ssao::evaluate(res[0].ao, ref).metrics.rmse, rmse2 = ssao::evaluate(res[1].ao, ref).metrics.rmse;
    std::printf("Filament AO on the corner at 96x54: RMSE %.4f (make peers), %.4f (2 R)\n", rmse, rmse2);
    EXPECT_NEAR(rmse, kFilamentRmse, kFilamentTolerance) << "make-peers settings on the corner at 96x54";
    EXPECT_NEAR(rmse2, kFilamentRmse2R, kFilamentTolerance) << "twice the radius";
    EXPECT_EQ(ssao::evaluate(res[2].ao, ref).metrics.rmse, rmse); // the timed frames draw the same AO
    EXPECT_EQ(runner.run({{0, {}, 0}})[0].ao.data, res[0].ao.data); // one image per setting in every session
}

TEST(CliEngineFilament, TuneWritesASnippetThatTurnsTheAoOn) {
    NEED_MODULES();
    const std::string scene = writeCornerGltf("engine_tune_filament.gltf");
    const std::string out = outDir("engine_tune_filament") + ".json", js = outDir("engine_tune_filament") + ".js";
    fs::remove(out), fs::remove(js);
    const CliRun r = ssaolab("tune --engine filament-ssao --scene " + scene + " --size 96x54 --views 2 --rounds 1 --grid 3 "
                             "--knob intensity --reference-rays 8 --timing-frames 2 --save-overfit --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("tuned Filament View ambient occlusion (web build) on 1 views"), std::string::npos) << r.out;
    const nlohmann::json j = ssao::readJsonFile(out, "tuned");
    EXPECT_EQ(j["version"], "1.53.4");
    ASSERT_EQ(j["settings"].size(), 1u) << j.dump(1);
    // setAmbientOcclusionOptions falls back to the defaults for what it is not given, enabled: false
    // among them: the call turns the AO on beside the tuned value.
    const nlohmann::json got = runSnippet("view", slurp(js), "tuned_filament");
    EXPECT_EQ(got, (nlohmann::json{{"setAmbientOcclusionOptions(enabled)", true},
                                   {"setAmbientOcclusionOptions(intensity)", j["settings"]["intensity"]}}))
        << slurp(js);
    expectCleanFailure(ssaolab("tune --engine filament-ssao --scene builtin:showcase --out " + out), "glTF");
    expectCleanFailure(ssaolab("tune --engine Filament-SSAO --scene " + scene + " --out " + out), "did you mean filament-ssao");
}
