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

namespace {
// The project headers a file includes, directly and through them (resolved against renderer/, the
// include root, and the including file's folder).
std::set<std::string> includeClosure(const std::string& file) {
    const fs::path root(SSAOLAB_SOURCE_DIR);
    std::set<std::string> seen;
    std::vector<fs::path> todo = {root / file};
    const std::regex inc(R"re(#include\s+"([^"]+)")re");
    while (!todo.empty()) {
        const fs::path p = todo.back();
        todo.pop_back();
        const std::string text = slurp(p);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), inc); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1];
            for (const fs::path& base : {root / "renderer", p.parent_path(), root / "app"}) {
                const fs::path cand = fs::weakly_canonical(base / name);
                if (!fs::exists(cand)) continue;
                const std::string rel = fs::relative(cand, root).generic_string();
                if (seen.insert(rel).second) todo.push_back(cand);
                break;
            }
        }
    }
    return seen;
}

bool includesGl(const std::string& file, std::string& via) {
    for (const auto& h : includeClosure(file)) {
        const std::string text = slurp(fs::path(SSAOLAB_SOURCE_DIR) / h);
        if (h.rfind("renderer/gl/", 0) == 0 || h == "renderer/renderer.h" || h.rfind("renderer/graph/frame_graph", 0) == 0 ||
            text.find("#include <epoxy/") != std::string::npos || text.find("#include <EGL/") != std::string::npos) {
            via = h;
            return true;
        }
    }
    return false;
}
} // namespace

TEST(Layering, ImagesMetricsReferenceAndReportsIncludeNoGlAndNoRenderer) {
    // The CPU image and its EXR/PNG writers, the error metrics, the ray-traced reference and the
    // reports (written from a FrameCapture) are pure CPU code: nothing they include, directly or
    // not, is GL (gl/, epoxy, EGL) or the renderer.
    int checked = 0;
    for (const auto& f : programSources()) {
        const bool pure = f.rfind("renderer/output/", 0) == 0 || f.rfind("renderer/metrics/", 0) == 0 ||
                          f.rfind("renderer/reference/", 0) == 0;
        if (!pure) continue;
        std::string via;
        EXPECT_FALSE(includesGl(f, via)) << f << " includes GL or the renderer through " << via;
        ++checked;
    }
    EXPECT_GE(checked, 20);
}

TEST(Layering, SettingsIncludeNoTechniqueCode) {
    // The settings see the techniques only through their settings structs (the one aggregate,
    // techniques/technique_settings.h) and what the registry supplies (settings/params.h).
    for (const auto& f : programSources()) {
        if (f.rfind("renderer/settings/", 0) != 0) continue;
        for (const auto& h : includeClosure(f)) {
            const bool technique = h.rfind("renderer/techniques/", 0) == 0;
            const bool settingsOnly = h == "renderer/techniques/technique_settings.h" ||
                                      h.find("/settings.h") != std::string::npos ||
                                      h == "renderer/techniques/noise/noise.h";
            EXPECT_FALSE(technique && !settingsOnly) << f << " includes " << h;
        }
    }
}
