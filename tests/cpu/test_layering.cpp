// The structure, checked on the source tree: an AO technique is its folders plus one registration
// (nothing else names it), and the layers include only what they may.
#include "techniques/technique.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using namespace ssao;

namespace {
std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Every source file of the program (not the tests), relative to the source root.
std::vector<std::string> programSources() {
    std::vector<std::string> out;
    const fs::path root(SSAOLAB_SOURCE_DIR);
    for (const char* top : {"renderer", "app", "shaders"})
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".cpp" || ext == ".h" || ext == ".glsl" || ext == ".frag" ||
                                        ext == ".vert" || ext == ".py"))
                out.push_back(fs::relative(e.path(), root).generic_string());
        }
    return out;
}
} // namespace

TEST(Layering, ATechniqueIsNamedOnlyInItsFoldersTheRegistryAndTheSettingsAggregate) {
    const std::vector<std::string> files = programSources();
    ASSERT_GT(files.size(), 50u);
    for (const auto& t : techniques()) {
        std::string type = t.id;
        type[0] = char(std::toupper(type[0]));
        // Its id as a string or key prefix, its folders, its settings member, its types.
        const std::regex names("\"" + t.id + "\"|\"" + t.id + "\\.|techniques/" + t.id + "/|\\." + t.id +
                               "\\.|\\b" + type + "(Settings|Constants|Quality|Noise|Module|Config)\\b");
        std::set<std::string> outside;
        for (const auto& f : files) {
            if (f.rfind("renderer/techniques/" + t.id + "/", 0) == 0 || f.rfind("shaders/techniques/" + t.id + "/", 0) == 0)
                continue;
            if (std::regex_search(slurp(fs::path(SSAOLAB_SOURCE_DIR) / f), names)) outside.insert(f);
        }
        std::string list;
        for (const auto& f : outside)
            list += " " + f;
        std::printf("%-6s named outside its folders in %zu files:%s\n", t.id.c_str(), outside.size(), list.c_str());
        const std::set<std::string> allowed = {"renderer/techniques/registry.cpp",
                                               "renderer/techniques/technique_settings.h"};
        for (const auto& f : outside)
            EXPECT_TRUE(allowed.count(f)) << t.id << " is named in " << f;
    }
}
