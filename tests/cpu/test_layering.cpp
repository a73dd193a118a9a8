// The structure, checked on the source tree: an AO technique is its folders plus one registration
// (nothing else names it), and the layers include only what they may.
#include "settings/params.h"
#include "techniques/technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
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
// The tests' and the scripts' sources (tests/, .ci/), relative to the source root: C++ or script.
std::vector<std::pair<std::string, bool>> testAndScriptSources() {
    std::vector<std::pair<std::string, bool>> out;
    const fs::path root(SSAOLAB_SOURCE_DIR);
    for (const char* top : {"tests", ".ci"})
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string(), name = e.path().filename().string();
            const bool cpp = ext == ".cpp" || ext == ".h";
            const bool script = ext == ".sh" || ext == ".py" || ext == ".js" || ext == ".mjs" || name == "CMakeLists.txt";
            if (e.is_regular_file() && (cpp || script))
                out.push_back({fs::relative(e.path(), root).generic_string(), script});
        }
    return out;
}
} // namespace

TEST(Layering, NoTestOrScriptKeepsAListOfTheTechniques) {
    // Adding a technique is its folders and the registrations, tests and scripts included: they take
    // the techniques from techniques() (scripts from `ssaolab techniques`) and each one's bounds,
    // levels and capabilities from its TechniqueInfo. A test may name one technique, or two it
    // compares, where it is about them; three or more in one statement (C++: up to a ';', its
    // #include lines aside; a script: a paragraph) is a hand-kept list a new technique would have to
    // join. In C++ a technique is named as in the program; in a script also as a word (ID-LEVEL).
    const std::vector<std::pair<std::string, bool>> files = testAndScriptSources();
    ASSERT_GT(files.size(), 50u);
    ASSERT_GE(techniques().size(), 3u);
    std::vector<std::regex> cppName, scriptName;
    for (const auto& t : techniques()) {
        std::string type = t.id;
        type[0] = char(std::toupper(type[0]));
        const std::string cpp = "\"" + t.id + "\"|\"" + t.id + "\\.|techniques/" + t.id + "/|\\." + t.id + "\\.|\\b" +
                                type + "(Settings|Constants|Quality|Noise|Module|Config)\\b";
        cppName.emplace_back(cpp);
        scriptName.emplace_back(cpp + "|[^\\w./-]" + t.id + "(-[a-z]+)?[^\\w/]");
    }
    const std::regex include("#include[^\\n]*"), paragraph("\\n[ \\t]*\\n");
    int lists = 0;
    for (const auto& [file, script] : files) {
        std::string text = slurp(fs::path(SSAOLAB_SOURCE_DIR) / file);
        if (!script) text = std::regex_replace(text, include, "");
        std::vector<std::string> chunks;
        if (script) {
            for (std::sregex_token_iterator it(text.begin(), text.end(), paragraph, -1), end; it != end; ++it)
                chunks.push_back(*it);
        } else {
            std::stringstream ss(text);
            for (std::string c; std::getline(ss, c, ';');) chunks.push_back(c);
        }
        for (const std::string& chunk : chunks) {
            const std::string padded = "\n" + chunk + "\n";
            std::string named;
            int n = 0;
            size_t first = padded.size();
            for (size_t i = 0; i < techniques().size(); ++i) {
                std::smatch m;
                if (!std::regex_search(padded, m, (script ? scriptName : cppName)[i])) continue;
                named += (n++ ? ", " : "") + techniques()[i].id;
                first = std::min(first, size_t(m.position(0)) + 1);
            }
            if (n < 3) continue;
            ++lists;
            const size_t from = padded.rfind('\n', first - 1) + 1, to = padded.find('\n', first);
            ADD_FAILURE() << file << " keeps a list of techniques (" << named << "): " << padded.substr(from, to - from);
        }
    }
    std::printf("%zu test and script files, %d lists of techniques\n", files.size(), lists);
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
    // The base types (the CPU image and its EXR/PNG writers, the settings blocks, a parameter row),
    // the error metrics, the ray-traced reference and the reports (written from a FrameCapture) are
    // pure CPU code: nothing they include, directly or not, is GL (gl/, epoxy, EGL) or the renderer.
    int checked = 0;
    for (const auto& f : programSources()) {
        const bool pure = f.rfind("renderer/base/", 0) == 0 || f.rfind("renderer/output/", 0) == 0 ||
                          f.rfind("renderer/metrics/", 0) == 0 || f.rfind("renderer/reference/", 0) == 0;
        if (!pure) continue;
        std::string via;
        EXPECT_FALSE(includesGl(f, via)) << f << " includes GL or the renderer through " << via;
        ++checked;
    }
    EXPECT_GE(checked, 20);
}

TEST(Layering, SettingsIncludeNoTechniqueCode) {
    // The settings see the techniques only through their settings structs (the one aggregate,
    // techniques/technique_settings.h) and what the registry supplies (techniques/registry.h).
    for (const auto& f : programSources()) {
        if (f.rfind("renderer/settings/", 0) != 0) continue;
        for (const auto& h : includeClosure(f)) {
            const bool technique = h.rfind("renderer/techniques/", 0) == 0;
            const bool settingsOnly = h == "renderer/techniques/technique_settings.h" || h == "renderer/techniques/registry.h" ||
                                      h.find("/settings.h") != std::string::npos ||
                                      h == "renderer/techniques/noise/noise.h";
            EXPECT_FALSE(technique && !settingsOnly) << f << " includes " << h;
        }
    }
}

namespace {
// renderer/'s floors, lowest first. A file includes its own folder and the floors below it; two
// folders on one floor include neither each other nor anything above. "renderer" stands for the
// files at renderer/'s top (renderer.h, renderer.cpp).
const std::vector<std::vector<std::string>> kRendererFloors = {
    {"util"},               // files, processes, errors, paths
    {"base"},               // GL-free value types: the CPU image, the shared settings blocks, a parameter row
    {"gl"},                 // the context, RAII handles, shaders, read-back
    {"scene"},              // meshes, cameras, view fitting, closed shells
    {"scene/load", "scene/gpu"}, // a scene from glTF or built in; the GPU scene, its culling and LOD
    {"graph", "reference"}, // the frame graph; the ray-traced reference (CPU)
    {"techniques"},         // the AO modules and the whole Settings (one member per technique)
    {"settings"},           // the parameter table and presets over Settings
    {"passes", "metrics"},  // the frame's other passes; the error metrics
    {"output", "renderer"}, // reports written from a FrameCapture; the Renderer that runs the frame
    {"display"},            // a frame read back from the Renderer and mapped for the eye
};

// The renderer/ folder of a path relative to renderer/ ("renderer" for its top-level files;
// scene/NAME for a folder inside scene/).
std::string rendererFolder(const std::string& rel) {
    const size_t slash = rel.find('/');
    if (slash == std::string::npos) return "renderer";
    const size_t second = rel.find('/', slash + 1);
    if (rel.compare(0, slash, "scene") == 0 && second != std::string::npos) return rel.substr(0, second);
    return rel.substr(0, slash);
}

// Each include arrow between two folders under `top` (renderer or app), resolved as the compiler
// does: the including file's folder first, then `top` and renderer/, the include roots. Folder
// pair -> "file -> header" lines.
std::map<std::pair<std::string, std::string>, std::vector<std::string>> arrowsIn(
    const std::string& top, std::string (*folder)(const std::string&)) {
    const fs::path src(SSAOLAB_SOURCE_DIR), root = src / top;
    const std::regex inc(R"re(#include\s+"([^"]+)")re");
    std::map<std::pair<std::string, std::string>, std::vector<std::string>> arrows;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        const std::string ext = e.path().extension().string();
        if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
        const std::string from = fs::relative(e.path(), root).generic_string();
        const std::string text = slurp(e.path());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), inc); it != std::sregex_iterator(); ++it) {
            for (const fs::path& base : {e.path().parent_path(), root, src / "renderer"}) {
                const fs::path cand = fs::weakly_canonical(base / std::string((*it)[1]));
                if (!fs::exists(cand)) continue;
                const std::string to = fs::relative(cand, root).generic_string();
                if (to.rfind("..", 0) != 0 && folder(from) != folder(to))
                    arrows[{folder(from), folder(to)}].push_back(from + " -> " + to);
                break;
            }
        }
    }
    return arrows;
}

// Fails on every arrow that points to the same floor or one above; returns the number of folder pairs.
int checkFloors(const std::string& top, const std::vector<std::vector<std::string>>& floors,
                std::string (*folder)(const std::string&), const std::vector<std::string>& folders) {
    std::map<std::string, size_t> floorOf;
    for (size_t i = 0; i < floors.size(); ++i)
        for (const auto& f : floors[i])
            floorOf[f] = i;
    for (const auto& f : folders)
        EXPECT_TRUE(floorOf.count(f)) << top << "/" << f << "/ has no floor";
    int up = 0, arrows = 0;
    for (const auto& [pair, lines] : arrowsIn(top, folder)) {
        const auto& [from, to] = pair;
        if (!floorOf.count(from) || !floorOf.count(to)) continue; // reported above
        ++arrows;
        if (floorOf[to] < floorOf[from]) continue;
        for (const auto& l : lines) {
            ADD_FAILURE() << top << "/" << l << ": " << from << " may not include " << to
                          << (floorOf[to] == floorOf[from] ? " (the same floor)" : " (a floor above)");
            ++up;
        }
    }
    std::printf("%d pairs of %s/ folders with includes between them; %d includes point up or sideways\n", arrows,
                top.c_str(), up);
    return arrows;
}

// The folders directly under `dir` (relative to the source root), each prefixed with `prefix`.
std::vector<std::string> foldersUnder(const std::string& dir, const std::string& prefix = "") {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(fs::path(SSAOLAB_SOURCE_DIR) / dir))
        if (e.is_directory()) out.push_back(prefix + e.path().filename().string());
    return out;
}

// app/'s floors, lowest first: the CLI layer every command shares; the measurement core and the
// web engines, shared by the commands and the explorer's front; the results every report is
// written from, and the front's measurers; one folder per command; the explorer's floors (its
// background measurers; the frame it draws and its state; the panels; the app that owns them
// all and its window); main.cpp.
const std::vector<std::vector<std::string>> kAppFloors = {
    {"cli"},
    {"measure", "engines"},
    {"results", "front"},
    {"commands/render", "commands/bench", "commands/merge", "commands/tune", "commands/skips", "commands/stress",
     "commands/docs", "commands/probe"},
    {"view/live"},
    {"view/frame"},
    {"view/panels"},
    {"view/app"},
    {"main"},
};

// An app/ file's floor folder: commands/NAME for a command, view/NAME for the explorer's, the first
// folder otherwise, "main" for main.cpp.
std::string appFolder(const std::string& rel) {
    const size_t slash = rel.find('/');
    if (slash == std::string::npos) return "main";
    const std::string first = rel.substr(0, slash);
    if (first != "commands" && first != "view") return first;
    const size_t second = rel.find('/', slash + 1);
    return second == std::string::npos ? first : rel.substr(0, second);
}
} // namespace

TEST(Layering, RendererFloorsPointDown) {
    std::vector<std::string> folders = foldersUnder("renderer");
    for (const auto& f : foldersUnder("renderer/scene", "scene/"))
        folders.push_back(f);
    EXPECT_GT(checkFloors("renderer", kRendererFloors, rendererFolder, folders), 20);
}

TEST(Layering, AppFloorsPointDown) {
    // One folder per command over the shared CLI layer; no command includes another or the explorer.
    std::vector<std::string> folders;
    for (const auto& f : foldersUnder("app"))
        if (f != "commands" && f != "view") folders.push_back(f);
    for (const char* two : {"commands", "view"})
        for (const auto& f : foldersUnder(std::string("app/") + two, std::string(two) + "/"))
            folders.push_back(f);
    EXPECT_GT(checkFloors("app", kAppFloors, appFolder, folders), 20);
}

TEST(Layering, ATechniqueDeclaresThePyramidTheRendererAdds) {
    // No technique includes passes/: one with a "<id>.pyramid" row declares the capability
    // (TechniqueInfo::pyramid) and the renderer adds passes/position_pyramid_pass.h from it.
    int withRow = 0;
    for (const auto& t : techniques()) {
        Settings s = defaultSettings();
        setParam(s, "ao.technique", t.id);
        if (!findParam(t.id + ".pyramid")) {
            EXPECT_FALSE(usesPyramid(s)) << t.id;
            continue;
        }
        ++withRow;
        ASSERT_TRUE(t.pyramid) << t.id << " has a pyramid row but declares no pyramid capability";
        setParam(s, t.id + ".pyramid", "true");
        EXPECT_TRUE(usesPyramid(s)) << t.id;
        setParam(s, t.id + ".pyramid", "false");
        EXPECT_FALSE(usesPyramid(s)) << t.id;
    }
    EXPECT_GE(withRow, 1);
}

TEST(Layering, PanelsTakeWhatTheyDrawAndReturnActions) {
    // The explorer's panels (app/view/panels/ui_*.cpp) are given the state they draw and return actions
    // (view/panels/ui_actions.h) that AppCore applies: none reaches into AppCore for a mutable part.
    const fs::path view = fs::path(SSAOLAB_SOURCE_DIR) / "app/view/panels";
    const std::regex core("\\bAppCore\\b|\"view/app/app_core\\.h\"");
    const std::regex accessor(
        "\\bapp(_|\\(\\))?(\\.|->)(view|settings|presets|front|frames|inspector|cameraController|renderer)\\(\\)");
    int panels = 0;
    for (const auto& e : fs::directory_iterator(view)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("ui_", 0) != 0 || e.path().extension() != ".cpp") continue;
        ++panels;
        const std::string text = slurp(e.path());
        EXPECT_FALSE(std::regex_search(text, core)) << name << " names AppCore: give the panel what it draws";
        std::smatch m;
        EXPECT_FALSE(std::regex_search(text, m, accessor)) << name << " calls " << m.str() << " of the app";
    }
    EXPECT_GE(panels, 5);
    // Each panel's entry point takes its state const; the one mutable reference is where its actions
    // go. The strip under the image keeps the parts it reads (its checkboxes, the inspector's cache).
    const std::string decls = slurp(view / "ui_panels.h");
    const std::regex entry("\\bvoid ((?:begin|draw)\\w+)\\(([^)]*)\\)");
    const std::regex mutableRef("(^|,)\\s*(?!const\\b)[\\w:<>]+&");
    const std::set<std::string> strip = {"drawInfoStrip", "drawReferenceSection"};
    int entries = 0;
    for (auto it = std::sregex_iterator(decls.begin(), decls.end(), entry); it != std::sregex_iterator(); ++it) {
        const std::string fn = (*it)[1], params = (*it)[2];
        if (strip.count(fn)) continue;
        ++entries;
        const std::string rest = std::regex_replace(params, std::regex("UiActions& out"), "");
        EXPECT_FALSE(std::regex_search(rest, mutableRef)) << fn << "(" << params << ") takes a mutable reference";
    }
    EXPECT_GE(entries, 7);
}

TEST(Layering, AFunctionAFolderDeclaresItDefines) {
    // A free function declared in a renderer/ header is defined in the same folder: one declared
    // below and defined above (base/ declaring what techniques/ defines) is an arrow back up that
    // no include shows.
    const fs::path root = fs::path(SSAOLAB_SOURCE_DIR) / "renderer";
    const std::regex decl(R"re((?:^|\n)(?!return|typedef|using|template|friend|static_assert)[A-Za-z_][\w:<>,*& ]*?[\s*&]([A-Za-z_]\w*)\(([^;{}]*)\)\s*(?:const)?\s*;)re");
    int declared = 0;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (!e.is_regular_file() || e.path().extension() != ".h") continue;
        const std::string text = slurp(e.path());
        std::string here; // the folder's own sources, headers included (inline and template definitions)
        for (const auto& f : fs::directory_iterator(e.path().parent_path()))
            if (f.is_regular_file() && (f.path().extension() == ".cpp" || f.path().extension() == ".h")) here += slurp(f.path());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), decl); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1];
            ++declared;
            const std::regex def("\\b" + name + R"re(\([^;{}]*\)\s*(const\s*)?(noexcept\s*)?\{)re");
            EXPECT_TRUE(std::regex_search(here, def))
                << fs::relative(e.path(), root).generic_string() << " declares " << name << " but its folder does not define it";
        }
    }
    EXPECT_GT(declared, 200);
}
