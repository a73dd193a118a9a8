// The benchmark's pure parts: viewpoints orbit the scene's camera without changing what it looks
// at or how far away it is; sweeps expand to the configurations they describe.
#include "measure/sweep.h"
#include "commands/tune/tune_guard.h"
#include "measure/viewpoints.h"
#include "settings/params.h"
#include "techniques/technique.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

using namespace ssao;

TEST(BenchViewpoints, OrbitsKeepTargetDistanceAndLens) {
    Camera c;
    c.eye = {3, 2, 5};
    c.target = {0.5f, 0.2f, -0.3f};
    c.fovYDeg = 50;
    const auto views = viewpoints(c, 5);
    ASSERT_EQ(views.size(), 5u);
    EXPECT_EQ(views[0].first, "camera");
    EXPECT_EQ(views[0].second.eye, c.eye);
    EXPECT_EQ(views[1].first, "orbit+25");
    EXPECT_EQ(views[2].first, "orbit-25");
    EXPECT_EQ(views[3].first, "orbit+50");
    const float dist = glm::length(c.eye - c.target);
    for (size_t i = 1; i < views.size(); ++i) {
        const Camera& v = views[i].second;
        EXPECT_EQ(v.target, c.target);
        EXPECT_EQ(v.fovYDeg, c.fovYDeg);
        EXPECT_NEAR(glm::length(v.eye - v.target), dist, 1e-3f * dist);
        EXPECT_GT(glm::length(v.eye - c.eye), 0.1f * dist) << views[i].first; // really another view
        validateCamera(v);
    }
}

TEST(BenchSweep, GroupsExpandToProductsDeduplicatedWithTheBaselineFirst) {
    const nlohmann::json j = nlohmann::json::parse(R"({
      "name": "t", "base": {"set": {"kernel.noise": "none"}},
      "groups": [{"name": "a", "vary": {"kernel.samples": [4, 8], "denoise.kind": ["none", "box4"]}},
                 {"name": "b", "set": {"kernel.samples": 4, "denoise.kind": "none"}}]})");
    const Sweep s = parseSweep(j, "test");
    // baseline + 2x2 products (group b repeats one of them) + every technique at its defaults over
    // the base (kernel: 64 samples, box4: not a duplicate).
    ASSERT_EQ(s.configs.size(), 1u + 4u + techniques().size());
    EXPECT_EQ(s.baseline, 0u);
    EXPECT_TRUE(s.configs[0].baseline);
    EXPECT_EQ(s.configs[0].label, "learnopengl (baseline)");
    EXPECT_EQ(s.configs[1].settings.kernel.samples, 4);
    EXPECT_EQ(s.configs[1].settings.kernel.noise, Noise::None); // the base applies
    // Labels name each key's group: "kind=none" alone did not say which parameter it was.
    EXPECT_EQ(s.configs[1].label, "denoise.kind=none kernel.noise=none kernel.samples=4");
    EXPECT_EQ(s.configs[4].settings.kernel.samples, 8);
    EXPECT_EQ(s.configs[5].group, "technique defaults");
}

TEST(BenchSweep, AllVariesEveryChoiceSoNoSweepListsTheTechniques) {
    const Sweep s = parseSweep(nlohmann::json::parse(R"({"groups": [{"name": "every", "vary": {"ao.technique": "all"}}]})"),
                               "test");
    std::vector<std::string> swept;
    for (const BenchConfig& c : s.configs)
        if (c.group == "every") swept.push_back(c.keys["ao.technique"].get<std::string>());
    std::vector<std::string> ids;
    for (const auto& t : techniques())
        ids.push_back(t.id);
    EXPECT_EQ(swept, ids);
    // The shipped sweep lists no group of every technique: a new one joins "all" by registering.
    std::ifstream in(std::string(SSAOLAB_SOURCE_DIR) + "/assets/bench/sweep_builtin.json");
    const nlohmann::json builtin = nlohmann::json::parse(in);
    int alls = 0;
    for (const auto& g : builtin["groups"]) {
        if (!g.contains("vary") || !g["vary"].contains("ao.technique")) continue;
        const nlohmann::json& v = g["vary"]["ao.technique"];
        alls += v == "all";
        if (v.is_array()) {
            EXPECT_LT(v.size(), 3u) << g.dump() << ": \"all\" instead of a list of the techniques";
        }
    }
    EXPECT_GE(alls, 1);
}

TEST(BenchSweep, AnyPresetCanBeTheBaseline) {
    const Sweep s = parseSweep(nlohmann::json::parse(R"({"groups": []})"), "test", "", 2000, "gtao-high");
    EXPECT_EQ(s.configs[s.baseline].label, "gtao-high (baseline)");
    EXPECT_EQ(s.configs[s.baseline].settings.ao.technique, "gtao");
    EXPECT_THROW(parseSweep(nlohmann::json::parse(R"({"groups": []})"), "test", "", 2000, "no-such-preset"), Error);
}

TEST(BenchSweep, TheBuiltinSweepCoversWhatTheIssueLists) {
    const Sweep s = loadSweep("builtin");
    std::set<int> samples;
    std::set<std::string> blurs, positions, normals, shapes;
    bool separable = false;
    for (const auto& c : s.configs) {
        samples.insert(c.settings.kernel.samples);
        blurs.insert(findParam("denoise.kind")->format(findParam("denoise.kind")->get(c.settings)));
        positions.insert(findParam("gbuffer.position_format")->format(findParam("gbuffer.position_format")->get(c.settings)));
        normals.insert(findParam("gbuffer.normal_format")->format(findParam("gbuffer.normal_format")->get(c.settings)));
        shapes.insert(findParam("kernel.shape")->format(findParam("kernel.shape")->get(c.settings)));
        separable |= c.settings.kernel.separable;
    }
    EXPECT_TRUE(samples.count(4) && samples.count(256));
    EXPECT_EQ(blurs.size(), findParam("denoise.kind")->choices.size());
    EXPECT_EQ(shapes.size(), findParam("kernel.shape")->choices.size());
    EXPECT_EQ(positions.size(), 2u);
    EXPECT_GE(normals.size(), 2u); // 8-bit and float normals
    EXPECT_TRUE(separable);
    // Issue 8: every technique, noise kind, normal source, resolution, the pyramid on and off,
    // temporal accumulation and the shipped tuned presets.
    std::set<std::string> techs, noises, sources, resolutions, presets;
    std::set<bool> pyramid, temporal;
    for (const auto& c : s.configs) {
        techs.insert(c.settings.ao.technique);
        if (c.settings.ao.technique == "gtao") {
            noises.insert(findParam("gtao.noise")->format(findParam("gtao.noise")->get(c.settings)));
            pyramid.insert(c.settings.gtao.pyramid);
        }
        sources.insert(findParam("ao.normals")->format(findParam("ao.normals")->get(c.settings)));
        resolutions.insert(findParam("ao.resolution")->format(findParam("ao.resolution")->get(c.settings)));
        temporal.insert(c.settings.temporal.enabled);
        if (c.keys.contains("preset")) presets.insert(c.keys["preset"].get<std::string>());
    }
    EXPECT_EQ(techs.size(), techniques().size());
    EXPECT_EQ(noises.size(), findParam("gtao.noise")->choices.size());
    EXPECT_EQ(sources.size(), 2u);
    EXPECT_EQ(resolutions.size(), 3u);
    EXPECT_EQ(pyramid.size(), 2u);
    EXPECT_EQ(temporal.size(), 2u);
    for (const char* p : {"gtao-high", "vbao-high", "sao-medium", "hbao-high"})
        EXPECT_TRUE(presets.count(p)) << p;
}

TEST(BenchSweep, BadSweepsAreRefusedNamingTheProblem) {
    auto fails = [](const char* text, const char* needle) {
        try {
            parseSweep(nlohmann::json::parse(text), "test");
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << "accepted: " << text;
    };
    fails(R"({"groups": [{"vary": {"kernel.samples": []}}]})", "non-empty");
    fails(R"({"groups": [{"vary": {"kernel.samples": "all"}}]})", "needs a parameter with choices");
    fails(R"({"groups": [{"vary": {"no.such_key": "all"}}]})", "needs a parameter with choices");
    fails(R"({"groups": [{"vary": {"ao.technique": "every"}}]})", "non-empty list");
    fails(R"({"groups": [{"vary": {"kernel.samples": [0]}}]})", "kernel.samples");
    fails(R"({"groups": [{"set": {"ao.radius_scene": 0.1}}]})", "radius");
    fails(R"({"groups": [{"sett": {}}]})", "sett");
    fails(R"({"grups": []})", "grups");
    fails(R"({"base": {"preset": "no-such-preset"}})", "no-such-preset");
    fails(R"({"groups": [{"preset": "no-such-preset"}]})", "no-such-preset");
    fails(R"({"groups": [{"preset": 3}]})", "preset name");
    // Found by tests/fuzz/fuzz_settings: a non-string name threw nlohmann's type_error, naming nothing.
    fails(R"({"name": [{"name": "a"}]})", "'name' must be a string");
    fails(R"({"description": 3})", "'description' must be a string");
    fails(R"({"base": {"preset": []}})", "'preset' must be a string");
    fails(R"({"groups": [{"name": {}}]})", "'name' must be a string");
    fails(R"({"groups": [3]})", "group 1 must be an object");
    fails(R"({"groups": [{"vary": {"kernel.samples": [1,2,3,4,5,6,7,8,9,10], "kernel.bias": [0,0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9], "kernel.seed": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21]}}]})",
          "more than");
}

// One configuration under two names (vbao's auto denoiser is none) is one configuration: measured
// once, listed once under its first name, the other kept as its alias.
TEST(BenchSweep, TwoNamesOfOneConfigurationAreOneConfigurationWithAnAlias) {
    const Sweep s = parseSweep(nlohmann::json::parse(R"({"groups": [
        {"name": "plain", "set": {"ao.technique": "vbao", "denoise.kind": "none"}},
        {"name": "again", "set": {"ao.technique": "vbao", "denoise.kind": "auto", "vbao.slices": 4}}]})"),
                               "test");
    ASSERT_EQ(s.configs.size(), 1u + 1u + techniques().size() - 1u); // baseline, plain, the others' defaults
    std::set<std::string> settings;
    for (const auto& c : s.configs) {
        EXPECT_NE(c.label, "vbao defaults");
        settings.insert(toEffectiveJson(c.settings).dump());
    }
    EXPECT_EQ(settings.size(), s.configs.size());
    const BenchConfig& plain = s.configs[1];
    EXPECT_EQ(plain.label, "ao.technique=vbao denoise.kind=none");
    EXPECT_EQ(plain.aliases, (std::vector<std::string>{"ao.technique=vbao denoise.kind=auto vbao.slices=4", "vbao defaults"}));
    // The built-in sweep lists no configuration twice either.
    const Sweep builtin = loadSweep("builtin");
    std::set<std::string> labels;
    for (const auto& c : builtin.configs)
        EXPECT_TRUE(labels.insert(c.label).second) << c.label;
}

// tune's guard: the held-out error is every held-out view's (a scene's weight is its views); a fit
// that leaves it where it was is kept, one that raises it is overfit, and a scene that got worse
// is named either way.
TEST(TuneGuard, TheHeldOutErrorOfEveryViewDecides) {
    const FitVerdict same = judgeFit({{"a", 0.01, 0.01, 2}});
    EXPECT_FALSE(same.overfit);
    EXPECT_TRUE(same.worse.empty());
    // b rises on 1 view, a falls on 3: better overall, b named.
    const FitVerdict mixed = judgeFit({{"a (held-out views)", 0.04, 0.01, 3}, {"b", 0.01, 0.02, 1}});
    EXPECT_FALSE(mixed.overfit);
    EXPECT_EQ(mixed.worse, std::vector<std::string>{"b"});
    EXPECT_DOUBLE_EQ(mixed.before, std::sqrt((0.04 * 3 + 0.01) / 4));
    EXPECT_DOUBLE_EQ(mixed.after, std::sqrt((0.01 * 3 + 0.02) / 4));
    // The same rise on 3 views outweighs the fall on 1.
    const FitVerdict worse = judgeFit({{"a", 0.04, 0.01, 1}, {"b", 0.01, 0.03, 3}});
    EXPECT_TRUE(worse.overfit);
    const std::string line = refusalText(worse, "t.json");
    EXPECT_NE(line.find("--save-overfit"), std::string::npos) << line;
    EXPECT_NE(line.find("b"), std::string::npos) << line;
    EXPECT_EQ(line.find('\n'), std::string::npos);
}

// A web engine's tune against its two baselines: the held-out views' error of the engine as its
// package ships it, and of its defaults with every length from R. A tune that beats the rescaled
// defaults (0.30 -> 0.184) but not what ships (0.15) is refused, naming the shipped baseline.
TEST(TuneGuard, AnEngineTuneIsJudgedAgainstTheBetterOfItsTwoBaselines) {
    const std::vector<HeldOutScore> shipped = {{"city (held-out views)", 0.15 * 0.15, 0.184 * 0.184, 5}};
    const std::vector<HeldOutScore> fromR = {{"city (held-out views)", 0.30 * 0.30, 0.184 * 0.184, 5}};
    EXPECT_FALSE(judgeFit(fromR).overfit) << "against the rescaled defaults alone it would pass";
    const FitVerdict v = judgeAgainstBetter(shipped, fromR);
    EXPECT_TRUE(v.overfit);
    EXPECT_EQ(v.baseline, "as shipped");
    EXPECT_NEAR(v.before, 0.15, 1e-12);
    const std::string line = refusalText(v, "n8ao.json");
    EXPECT_NE(line.find("against the engine as shipped"), std::string::npos) << line;
    // Where the rescaled defaults are the better baseline, they are the one judged against.
    const FitVerdict r = judgeAgainstBetter(fromR, shipped);
    EXPECT_EQ(r.baseline, "with lengths from R");
    EXPECT_TRUE(r.overfit);
    const FitVerdict kept = judgeAgainstBetter({{"a", 0.04, 0.01, 2}}, {{"a", 0.05, 0.01, 2}});
    EXPECT_FALSE(kept.overfit);
    EXPECT_EQ(kept.baseline, "as shipped");
}
