// One default everywhere: a run with nothing set renders what the window opens on (the start
// preset), and `ssaolab params` lists that as the default.
#include "cli_run.h"
#include "settings/preset.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace ssaotest;

TEST(CliDefaults, RenderWithoutAPresetIsTheWindowsFirstFrame) {
    const std::string plain = outDir("default_plain"), start = outDir("default_start");
    CliRun r = ssaolab("render --scene builtin:corner --size 64x36 --timing-frames 1 --quiet --out " + plain);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = ssaolab("render --scene builtin:corner --size 64x36 --timing-frames 1 --quiet --preset " +
                std::string(ssao::kStartPreset) + " --out " + start);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto a = nlohmann::json::parse(slurp(plain + "/metrics.json"));
    const auto b = nlohmann::json::parse(slurp(start + "/metrics.json"));
    EXPECT_EQ(a["settings"], b["settings"]);
    EXPECT_EQ(a["settings"]["ao"]["technique"], "vbao");
}

TEST(CliDefaults, ParamsListsTheStartPresetsValuesAsDefaults) {
    const CliRun r = ssaolab("params");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find(std::string("the start preset ") + ssao::kStartPreset), std::string::npos) << r.out;
    std::istringstream in(r.out);
    std::string technique;
    for (std::string line; std::getline(in, line);)
        if (line.rfind("ao.technique ", 0) == 0) technique = line;
    ASSERT_FALSE(technique.empty()) << r.out;
    std::istringstream cols(technique);
    std::string key, value;
    cols >> key >> value;
    EXPECT_EQ(value, "vbao") << technique;
    EXPECT_NE(technique.find("[base kernel]"), std::string::npos) << technique;
}
