// Whole program: `ssaolab tune` saves only a fit that holds on what it never fitted (its held-out
// views and scenes), and moves only the knobs it was asked to fit or the technique's default set.
#include "cli_run.h"

#include "settings/params.h"
#include "settings/preset.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <set>

using namespace ssaotest;

namespace {

const std::string kTiny = " --size 64x36 --views 2 --rounds 1 --grid 3 --reference-rays 8 --quiet";

std::string freshDir(const std::string& name) {
    const std::string dir = outDir(name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// The two numbers of "... rose A -> B ...".
std::pair<double, double> rose(const std::string& text) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex("rose ([0-9.]+) -> ([0-9.]+)"))) return {NAN, NAN};
    return {std::stod(m[1]), std::stod(m[2])};
}

// Every parameter key whose value in the saved preset differs from `start`.
std::set<std::string> moved(const ssao::Settings& start, const std::string& preset) {
    const ssao::Settings saved = ssao::readPresetFile(preset).settings;
    std::set<std::string> out;
    for (const ssao::Param& p : ssao::paramTable())
        if (p.get(saved) != p.get(start)) out.insert(p.key);
    return out;
}

ssao::Settings startOf(const std::string& technique) {
    ssao::Settings s = ssao::defaultSettings();
    ssao::setParam(s, "ao.technique", technique);
    return s;
}

} // namespace

// Fitted on an open plane from a bias of 0 (the plane darkens itself), the kernel's bias climbs to
// the top of its range: right for the plane, too bright on a corner the fit never saw.
TEST(CliTuneGuard, AFitThatRaisesTheHeldOutErrorIsRefusedUnlessAskedAndThenSavedLoudly) {
    const std::string dir = freshDir("tune_guard");
    const std::string args = "tune --technique kernel --set kernel.bias=0 --scene builtin:plane "
                             "--held-out-scene builtin:corner" + kTiny;
    CliRun r = ssaolab(args + " --out " + dir + "/refused.json");
    expectCleanFailure(r, "--save-overfit");
    EXPECT_EQ(r.err.rfind("ssaolab: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/refused.json"));
    const auto [before, after] = rose(r.err);
    EXPECT_GT(after, before) << r.err; // both numbers, the rise
    EXPECT_GT(before, 0.0) << r.err;

    r = ssaolab(args + " --save-overfit --out " + dir + "/saved.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("ssaolab: warning: "), std::string::npos) << r.err;
    EXPECT_EQ(rose(r.err), std::make_pair(before, after)) << r.err;
    const auto j = nlohmann::json::parse(slurp(dir + "/saved.json"));
    EXPECT_TRUE(j["scores"].value("overfit", false)) << j["scores"].dump();
    EXPECT_NE(j["description"].get<std::string>().find("overfit"), std::string::npos);
}

// SAO from a weak intensity, fitted on the corner: stronger AO helps the slabs a lot and darkens the
// open plane a little. Overall the held-out error falls, so the preset is saved, with a warning
// naming the plane.
TEST(CliTuneGuard, AHeldOutSceneThatGetsWorseIsNamedWhenTheWholeGetsBetter) {
    const std::string dir = freshDir("tune_guard_mixed");
    CliRun r = ssaolab("tune --technique sao --set sao.intensity=0.2 --scene builtin:corner --held-out-scene "
                       "builtin:plane --held-out-scene builtin:slabs" + kTiny + " --out " + dir + "/t.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir + "/t.json"));
    EXPECT_NE(r.err.find("ssaolab: warning: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("builtin:plane"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("builtin:slabs"), std::string::npos) << r.err;
}

// The README: the technique's own float rows by default, but never a radius multiplier (tune's, or
// GTAO's own gtao.radius_multiplier, which lengthens its search past R) nor ao.power unless named;
// with --knob, only the named knobs. Every other key of the saved preset is the start's.
TEST(CliTuneGuard, AKnobThatIsNeitherNamedNorInTheDefaultSetNeverMoves) {
    const std::string dir = freshDir("tune_knobs");
    const ssao::Settings start = startOf("gtao");
    // Fitted on the corner, GTAO at its defaults wants a longer search (1.457 -> 2.55 when allowed).
    CliRun r = ssaolab("tune --technique gtao --scene builtin:corner --held-out-scene builtin:slabs" + kTiny +
                       " --out " + dir + "/default.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::set<std::string> defaultSet = {"gtao.falloff_range", "gtao.distribution_power", "gtao.thin_compensation"};
    const std::set<std::string> m = moved(start, dir + "/default.json");
    EXPECT_FALSE(m.empty()) << "nothing was fitted";
    for (const std::string& k : m)
        EXPECT_TRUE(defaultSet.count(k)) << k << " moved though no --knob named it";

    r = ssaolab("tune --technique gtao --knob gtao.falloff_range --scene builtin:corner --held-out-scene builtin:slabs" +
                kTiny + " --out " + dir + "/named.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& k : moved(start, dir + "/named.json"))
        EXPECT_EQ(k, "gtao.falloff_range") << k << " moved though only gtao.falloff_range was named";

    // Named, GTAO's own multiplier is fitted.
    r = ssaolab("tune --technique gtao --knob gtao.radius_multiplier --scene builtin:corner --held-out-scene "
                "builtin:slabs" + kTiny + " --out " + dir + "/multiplier.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(moved(start, dir + "/multiplier.json"), std::set<std::string>{"gtao.radius_multiplier"});
}

TEST(CliTuneGuard, AFittedValueAtAnEdgeOfItsRangeIsNamedAndTheStartIsNamedAsSuch) {
    const std::string base = "tune --scene builtin:corner --size 64x36 --views 2 --rounds 1 --grid 3 --reference-rays 4 "
                             "--save-overfit ";
    const std::string edge = outDir("tune_edge") + ".json", inside = outDir("tune_inside") + ".json";
    const CliRun r = ssaolab(base + "--technique sao --knob sao.bias --out " + edge);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("ssaolab: warning: tuned sao.bias = 0 is the bottom of its range"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the optimum may lie beyond"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("start (the technique's defaults) -> tuned"), std::string::npos) << r.out;
    const nlohmann::json j = nlohmann::json::parse(slurp(edge));
    EXPECT_EQ(j["scores"]["at_range_edge"], nlohmann::json::array({"sao.bias"}));
    EXPECT_EQ(j["scores"]["start_point"], "the technique's defaults");
    EXPECT_TRUE(j["scores"]["start"]["train"].is_number());
    const CliRun in = ssaolab(base + "--technique gtao --knob gtao.distribution_power --out " + inside);
    ASSERT_EQ(in.exitCode, 0) << in.err;
    EXPECT_EQ(in.err.find("optimum may lie beyond"), std::string::npos) << in.err;
    EXPECT_EQ(nlohmann::json::parse(slurp(inside))["scores"]["at_range_edge"], nlohmann::json::array());
}
