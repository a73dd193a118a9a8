// User techniques as techniques (techniques/user/user_technique.h, user_folder.h): registered,
// they add an ao.technique choice and rows "user.NAME.*" with the header's ranges and defaults; a
// new version replaces the old without invalidating what callers hold; a preset names the file
// and its hash and says when the file has changed; the folder is read through the file gate.
#include "settings/params.h"
#include "settings/preset.h"
#include "techniques/technique.h"
#include "techniques/user/user_folder.h"
#include "techniques/user/user_technique.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace ssao;
using ssaotest::errorOf;

namespace {

std::string header(const std::string& def = "1.0") {
    return "/*ssaolab\ninterface = 1;\nlabel = \"Mine\";\n"
           "uniform float strength < ui_min = 0.5; ui_max = 4.0; ui_label = \"Strength\"; ui_units = \"x\";\n"
           "    ui_tooltip = \"How dark.\"; > = " + def + ";\n"
           "uniform int taps < ui_min = 1; ui_max = 32; > = 8;\n"
           "uniform int falloff < ui_type = \"combo\"; ui_items = \"none\\0linear\\0\"; > = 1;\n"
           "*/\nfloat ssaoUserAo() { return 1.0; }\n";
}

std::shared_ptr<const UserTechnique> mine(const std::string& text) {
    return std::make_shared<UserTechnique>(loadUserTechnique(text, "dir/mine.ao.glsl", builtinTechniqueIds()));
}

std::string folder(const std::string& name) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// Each test leaves the built-ins alone registered, as every other test expects.
class UserRegistry : public ::testing::Test {
  protected:
    void TearDown() override { setUserTechniques({}); }
};

} // namespace

TEST_F(UserRegistry, AUserTechniqueIsAChoiceWithItsHeadersRows) {
    setUserTechniques({mine(header())});
    const Param* t = findParam("ao.technique");
    ASSERT_NE(t, nullptr);
    EXPECT_NE(std::find(t->choices.begin(), t->choices.end(), "user.mine"), t->choices.end());
    const Param* strength = findParam("user.mine.strength");
    ASSERT_NE(strength, nullptr);
    EXPECT_EQ(strength->group(), "user.mine");
    EXPECT_EQ(strength->name(), "strength");
    EXPECT_EQ(strength->label, "Strength");
    EXPECT_EQ(strength->help, "How dark.");
    EXPECT_EQ(strength->unit, "x");
    EXPECT_EQ(strength->min, 0.5);
    EXPECT_EQ(strength->max, 4.0);
    EXPECT_EQ(strength->def, 1.0);
    const Param* falloff = findParam("user.mine.falloff");
    ASSERT_NE(falloff, nullptr);
    EXPECT_EQ(falloff->type, Param::Type::Enum);
    EXPECT_EQ(falloff->choices, (std::vector<std::string>{"none", "linear"}));
    EXPECT_EQ(falloff->format(falloff->def), "linear");
    ASSERT_NE(findParam("user.mine.ssao_noise"), nullptr);
    // Its rows apply while it is chosen, and --set checks them like any other.
    Settings s = defaultSettings();
    EXPECT_FALSE(strength->applies(s));
    setParam(s, "ao.technique", "user.mine");
    EXPECT_TRUE(strength->applies(s));
    setParam(s, "user.mine.strength", "2.5");
    EXPECT_EQ(userParamValues(*mine(header()), s), (std::vector<double>{2.5, 8, 1}));
    EXPECT_NE(errorOf([&] { setParam(s, "user.mine.strength", "9"); }).find("out of range [0.5, 4]"), std::string::npos);
    EXPECT_NE(errorOf([&] { setParam(s, "user.mine.taps", "2.5"); }).find("not an integer"), std::string::npos);
    validateSettings(s);
    // JSON: the group is the technique's id.
    EXPECT_EQ(toJson(s)["user.mine"]["strength"], 2.5);
    Settings back = defaultSettings();
    applyJson(back, toJson(s), "round trip");
    EXPECT_TRUE(back == s);
}

TEST_F(UserRegistry, ANewVersionReplacesTheRowsAndWhatCallersHeldStaysValid) {
    setUserTechniques({mine(header("1.0"))});
    const unsigned before = techniquesGeneration();
    const std::vector<Param>& oldTable = paramTable();
    const Param* oldRow = findParam("user.mine.strength");
    ASSERT_NE(oldRow, nullptr);
    setUserTechniques({mine(header("2.0"))});
    EXPECT_GT(techniquesGeneration(), before);
    EXPECT_EQ(findParam("user.mine.strength")->def, 2.0);
    EXPECT_EQ(oldRow->def, 1.0); // the old table is kept, unchanged
    EXPECT_FALSE(oldTable.empty());
    EXPECT_NE(findTechnique("user.mine").version, "");
    setUserTechniques({});
    EXPECT_EQ(findParam("user.mine.strength"), nullptr);
    EXPECT_NE(errorOf([] { findTechnique("user.mine"); }).find("unknown AO technique"), std::string::npos);
}

TEST_F(UserRegistry, ARefusedFilesReasonIsTheErrorOfChoosingIt) {
    setUserTechniques({}, {{"user.broken", "dir/broken.ao.glsl:3: expected ';'"}});
    EXPECT_EQ(errorOf([] { findTechnique("user.broken"); }),
              "technique user.broken was not loaded: dir/broken.ao.glsl:3: expected ';'");
}

TEST_F(UserRegistry, APresetNamesTheFileAndHashAndSaysWhenItChanged) {
    const auto v1 = mine(header("1.0"));
    const auto other = std::make_shared<UserTechnique>(
        loadUserTechnique(header(), "dir/other.ao.glsl", builtinTechniqueIds()));
    setUserTechniques({v1, other});
    Preset p;
    p.name = "mine-dark";
    setParam(p.settings, "ao.technique", "user.mine");
    setParam(p.settings, "user.mine.strength", "3");
    const nlohmann::json j = presetToJson(p);
    ASSERT_TRUE(j.contains("technique_file"));
    EXPECT_EQ(j["technique_file"]["id"], "user.mine");
    EXPECT_EQ(j["technique_file"]["file"], "mine.ao.glsl");
    EXPECT_EQ(j["technique_file"]["hash"], v1->hash);
    EXPECT_FALSE(j.contains("user.other")) << "another user technique's rows would tie the preset to its file";
    // The same file: no warning, the same settings.
    Preset same = presetFromJson(j, "mine-dark.json");
    EXPECT_TRUE(same.warnings.empty());
    EXPECT_TRUE(same.settings == p.settings);
    // The file changed (a new default): the preset still opens, and says so.
    const auto v2 = mine(header("1.5"));
    setUserTechniques({v2});
    Preset changed = presetFromJson(j, "mine-dark.json");
    ASSERT_EQ(changed.warnings.size(), 1u);
    EXPECT_NE(changed.warnings[0].find("mine.ao.glsl has changed since the preset was saved"), std::string::npos)
        << changed.warnings[0];
    EXPECT_NE(changed.warnings[0].find(v1->hash), std::string::npos);
    EXPECT_NE(changed.warnings[0].find(v2->hash), std::string::npos);
    EXPECT_EQ(changed.settings.ao.technique, "user.mine");
    // Not loaded at all: one error naming the technique and its file.
    setUserTechniques({});
    const std::string e = errorOf([&] { presetFromJson(j, "mine-dark.json"); });
    EXPECT_NE(e.find("uses the user technique user.mine (mine.ao.glsl), which is not loaded"), std::string::npos) << e;
    // A patch with a missing technique's keys and no technique_file says which technique is missing.
    const std::string k = errorOf([] { Settings s; applyJson(s, nlohmann::json::parse(R"({"user.gone": {"x": 1}})"), "p.json"); });
    EXPECT_NE(k.find("the user technique user.gone is not loaded"), std::string::npos) << k;
    // A built-in preset saved while user techniques are loaded carries none of them.
    setUserTechniques({v1});
    Preset builtin;
    EXPECT_FALSE(presetToJson(builtin).contains("user.mine"));
    EXPECT_FALSE(presetToJson(builtin).contains("technique_file"));
}

TEST_F(UserRegistry, TheFolderLoadsItsTechniquesAndRefusesBadFilesByLine) {
    const std::string dir = folder("user_folder");
    ssaotest::writeTemp("user_folder/mine.ao.glsl", header());
    ssaotest::writeTemp("user_folder/broken.ao.glsl", "/*ssaolab\ninterface = 1;\nuniform float x < ui_min = 0; > = 0;\n*/\n");
    ssaotest::writeTemp("user_folder/notes.txt", "not a technique");
    ssaotest::writeTemp("user_folder/Bad-Name.ao.glsl", header());
    std::filesystem::create_directories(dir + "/sub");
    ssaotest::writeTemp("user_folder/sub/deep.ao.glsl", header()); // only the folder's own files
    std::filesystem::create_symlink(dir + "/mine.ao.glsl", dir + "/linked.ao.glsl"); // links are not followed
    const UserTechniqueScan scan = scanUserTechniques(dir, true);
    ASSERT_EQ(scan.loaded.size(), 1u);
    EXPECT_EQ(scan.loaded[0]->name, "mine");
    ASSERT_EQ(scan.refused.size(), 2u);
    for (const auto& [id, why] : scan.refused) {
        std::printf("%s: %s\n", id.c_str(), why.c_str());
        EXPECT_EQ(why.find('\n'), std::string::npos);
        EXPECT_EQ(why.rfind(dir + "/", 0), 0u) << why;
    }
    EXPECT_EQ(scan.refused[1].first, "user.broken");
    EXPECT_EQ(scan.refused[1].second.rfind(dir + "/broken.ao.glsl:3: ", 0), 0u) << scan.refused[1].second;
    // A folder the user named must exist; the default one may not.
    EXPECT_NE(errorOf([&] { scanUserTechniques(dir + "/absent", true); }).find("does not exist"), std::string::npos);
    EXPECT_TRUE(scanUserTechniques(dir + "/absent", false).loaded.empty());
    EXPECT_NE(errorOf([&] { scanUserTechniques(dir + "/notes.txt", true); }).find("is not a folder"), std::string::npos);
    // Too large: refused by line 1, never read whole.
    ssaotest::writeTemp("user_folder/huge.ao.glsl", header() + std::string(kMaxUserFileBytes, ' '));
    const UserTechniqueScan big = scanUserTechniques(dir, true);
    bool found = false;
    for (const auto& [id, why] : big.refused)
        if (id == "user.huge") found = why == dir + "/huge.ao.glsl:1: the file is larger than 256 KiB";
    EXPECT_TRUE(found);
}

TEST_F(UserRegistry, TheDefaultFolderFollowsTheEnvironmentAndAnEmptyVariableIsUnset) {
    setenv("SSAOLAB_TECHNIQUE_DIR", "/somewhere/techniques", 1);
    EXPECT_EQ(defaultUserTechniqueDir(), "/somewhere/techniques");
    setenv("SSAOLAB_TECHNIQUE_DIR", "", 1);
    setenv("XDG_CONFIG_HOME", "/cfg", 1);
    EXPECT_EQ(defaultUserTechniqueDir(), "/cfg/ssaolab/techniques");
    unsetenv("XDG_CONFIG_HOME");
    setenv("HOME", "/home/u", 1);
    EXPECT_EQ(defaultUserTechniqueDir(), "/home/u/.config/ssaolab/techniques");
}

TEST_F(UserRegistry, AFloatAtTheEndOfItsRangePacksAsTheRowHoldsIt) {
    // The row stores a float (0.01 -> 0.0099999998): packing compares at that precision, so the
    // range's own end, as tune and the slider reach it, is inside.
    const auto t = std::make_shared<UserTechnique>(loadUserTechnique(
        "/*ssaolab\ninterface = 1;\nuniform float k < ui_min = 0.01; ui_max = 0.3; > = 0.1;\n*/\nfloat ssaoUserAo() { return 1.0; }\n",
        "dir/ends.ao.glsl", builtinTechniqueIds()));
    setUserTechniques({t});
    Settings s = defaultSettings();
    setParam(s, "user.ends.k", "0.01");
    validateSettings(s);
    EXPECT_EQ(packUserParams(t->header, userParamValues(*t, s)).size(), 16u);
    setParam(s, "user.ends.k", "0.3");
    EXPECT_EQ(packUserParams(t->header, userParamValues(*t, s)).size(), 16u);
}

TEST_F(UserRegistry, AHostileTechniqueFileFieldIsOneBoundedLine) {
    setUserTechniques({mine(header())});
    // Wrong types: one error naming the field's shape.
    for (const char* bad : {R"({"technique_file": 3})", R"({"technique_file": {"id": 1, "hash": "x"}})",
                            R"({"technique_file": {"id": "user.mine"}})", R"({"technique_file": []})"}) {
        const std::string e = errorOf([&] { presetFromJson(nlohmann::json::parse(bad), "p.json"); });
        EXPECT_NE(e.find("technique_file must be"), std::string::npos) << bad << ": " << e;
    }
    // A huge name with control bytes and shell syntax: clipped, and only ever text.
    nlohmann::json j = {{"technique_file",
                         {{"id", "user.gone$(touch x)\n" + std::string(100000, 'a')}, {"file", std::string(100000, 'b')},
                          {"hash", "0"}}}};
    const std::string e = errorOf([&] { presetFromJson(j, "p.json"); });
    EXPECT_NE(e.find("which is not loaded"), std::string::npos) << e.substr(0, 200);
    EXPECT_LT(e.size(), 400u);
    j["technique_file"]["id"] = "user.mine";
    const Preset p = presetFromJson(j, "p.json");
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_LT(p.warnings[0].size(), 400u);
}
