// Every project path the sources name in a comment, a string or an #include exists, so a comment
// that points a reader somewhere points at a real file; and no comment or parameter help quotes a
// timing measured on one machine (say why, and name the docs/bench page that measures it).
//
// The rule, on renderer/, app/, shaders/, tests/, .ci/, the Makefile and every CMakeLists.txt:
// - #include "x": must resolve (angle-bracket includes are other projects' headers).
// - any other token: a run of [A-Za-z0-9_./-] with a folder and a known extension (see kExts), whose
//   first folder is a folder name of the project tree (so npm imports, output folders and
//   placeholders such as dir/ or out/ are not project paths); skipped when a component is a
//   placeholder in capitals (ID, NAME, OUT), when it is absolute or a URL, or under ../shared.
// - in C++, GLSL and JS files only comments and string literals count; in tests/ only comments
//   (the strings there are fixtures the test writes, and a stale real one fails its own test).
// - resolved against the repository root, the include roots (renderer/, app/, tests/ and its
//   cli/, gl/, app/, shaders/), docs/ (scripts write links relative to it) and the file's folder.
#include "settings/params.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
const fs::path kRoot(SSAOLAB_SOURCE_DIR);
const char* const kExts[] = {".h",    ".cpp",  ".md",  ".sh", ".py",   ".json", ".glsl",
                             ".frag", ".vert", ".mjs", ".js", ".html", ".png",  ".csv"};
const char* const kTrees[] = {"renderer", "app", "shaders", "tests", ".ci", "docs", "assets"};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool cLike(const std::string& rel) {
    for (const char* e : {".h", ".cpp", ".glsl", ".frag", ".vert", ".js", ".mjs"})
        if (endsWith(rel, e)) return true;
    return false;
}

// The files scanned, relative to the root.
std::vector<std::string> scannedFiles() {
    std::vector<std::string> out = {"Makefile", "CMakeLists.txt"};
    for (const char* top : {"renderer", "app", "shaders", "tests", ".ci"})
        for (auto it = fs::recursive_directory_iterator(kRoot / top);
             it != fs::recursive_directory_iterator(); ++it) {
            const std::string name = it->path().filename().string();
            if (it->is_directory() && (name == "node_modules" || name == "seeds"))
                it.disable_recursion_pending();
            if (!it->is_regular_file()) continue;
            const std::string rel = fs::relative(it->path(), kRoot).generic_string();
            bool scanned = cLike(rel) || name == "CMakeLists.txt" || rel == ".ci/run";
            for (const char* e : {".py", ".sh", ".html"})
                scanned = scanned || endsWith(rel, e);
            if (scanned) out.push_back(rel);
        }
    return out;
}

// Every folder name of the project tree: a token's first folder must be one to be a project path.
const std::set<std::string>& folderNames() {
    static const std::set<std::string> names = [] {
        std::set<std::string> s;
        for (const char* top : kTrees) {
            s.insert(top);
            for (auto it = fs::recursive_directory_iterator(kRoot / top);
                 it != fs::recursive_directory_iterator(); ++it)
                if (it->is_directory()) {
                    if (it->path().filename() == "node_modules")
                        it.disable_recursion_pending();
                    else
                        s.insert(it->path().filename().string());
                }
        }
        return s;
    }();
    return names;
}

bool resolves(const std::string& rel, const std::string& token) {
    const fs::path own = (kRoot / rel).parent_path();
    for (const fs::path& base :
         {kRoot, kRoot / "renderer", kRoot / "app", kRoot / "tests", kRoot / "tests/cli", kRoot / "tests/gl",
          kRoot / "tests/app", kRoot / "shaders", kRoot / "docs", own})
        if (fs::exists(base / token)) return true;
    return false;
}

// A C-like file's comments and (when kept) string literals; code, and every #include line, become
// spaces, newlines stay so line numbers hold.
std::string commentsAndStrings(const std::string& text, bool keepStrings) {
    std::string out(text.size(), ' ');
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') out[i] = '\n';
    auto keep = [&](size_t from, size_t to, bool yes) {
        for (size_t k = from; k < to && k < text.size(); ++k)
            if (yes) out[k] = text[k];
    };
    bool lineHead = true; // only blanks since the last newline
    for (size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (c == '\n' || ((c == ' ' || c == '\t') && lineHead)) {
            lineHead = lineHead || c == '\n';
            ++i;
            continue;
        }
        const bool head = lineHead;
        lineHead = false;
        if (head && c == '#' && text.find_first_not_of(" \t", i + 1) == text.find("include", i + 1)) {
            i = std::min(text.find('\n', i), text.size()); // an #include line: checked on its own
            continue;
        }
        if (text.compare(i, 2, "//") == 0) {
            const size_t eol = std::min(text.find('\n', i), text.size());
            keep(i, eol, true);
            i = eol;
        } else if (text.compare(i, 2, "/*") == 0) {
            const size_t end = std::min(text.find("*/", i + 2), text.size());
            keep(i, end, true);
            i = end + 2;
        } else if (c == 'R' && i + 1 < text.size() && text[i + 1] == '"' &&
                   (i == 0 || !(std::isalnum((unsigned char)text[i - 1]) || text[i - 1] == '_'))) {
            const size_t open = text.find('(', i);
            const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
            const size_t end = std::min(text.find(close, open), text.size());
            keep(i, end + close.size(), keepStrings);
            i = end + close.size();
        } else if (c == '"' || c == '\'' || c == '`') {
            size_t j = i + 1;
            while (j < text.size() && text[j] != c && (text[j] != '\n' || c == '`'))
                j += text[j] == '\\' ? 2 : 1;
            keep(i, j + 1, keepStrings);
            i = j + 1;
        } else {
            ++i;
        }
    }
    return out;
}

bool placeholder(const std::string& part) {
    const std::string stem = part.substr(0, part.find('.'));
    bool letter = false;
    for (char ch : stem) {
        if (std::islower((unsigned char)ch)) return false;
        letter = letter || std::isupper((unsigned char)ch);
    }
    return letter;
}

// A token names a project path when it has a folder, a known extension and a first folder of the
// tree, and is no placeholder, absolute path, URL or path under ../shared.
bool projectPath(std::string token) {
    if (token.empty() || token[0] == '/' || token.find('/') == std::string::npos) return false;
    if (std::none_of(std::begin(kExts), std::end(kExts), [&](const char* e) { return endsWith(token, e); }))
        return false;
    if (token.compare(0, 10, "../shared/") == 0 || token.compare(0, 7, "shared/") == 0) return false;
    std::vector<std::string> parts;
    std::stringstream ss(token);
    for (std::string p; std::getline(ss, p, '/');)
        if (p != "." && p != ".." && !p.empty()) parts.push_back(p);
    if (parts.size() < 2 || !folderNames().count(parts[0])) return false;
    return std::none_of(parts.begin(), parts.end(), placeholder);
}

struct Finding {
    int line;
    std::string token;
};

// The paths `text` (the file `rel`) names that do not exist; `checked` counts those looked at.
std::vector<Finding> stalePaths(const std::string& rel, const std::string& text, int& checked) {
    std::vector<Finding> out;
    const bool c = cLike(rel);
    const std::string kept = c ? commentsAndStrings(text, rel.compare(0, 6, "tests/") != 0) : text;
    std::stringstream lines(text), keptLines(kept);
    std::string line, keptLine;
    for (int n = 1; std::getline(lines, line) && std::getline(keptLines, keptLine); ++n) {
        const size_t hash = line.find_first_not_of(" \t");
        if (c && hash != std::string::npos && line[hash] == '#' &&
            line.find_first_not_of(" \t", hash + 1) == line.find("include", hash + 1)) {
            const size_t q = line.find('"');
            if (q == std::string::npos) continue; // <...>: another project's header
            const std::string name = line.substr(q + 1, line.find('"', q + 1) - q - 1);
            ++checked;
            if (!resolves(rel, name)) out.push_back({n, name});
            continue;
        }
        for (size_t i = 0; i < keptLine.size();) {
            auto pathChar = [](char ch) {
                return std::isalnum((unsigned char)ch) || ch == '_' || ch == '.' || ch == '/' || ch == '-';
            };
            if (!pathChar(keptLine[i])) {
                ++i;
                continue;
            }
            size_t j = i;
            while (j < keptLine.size() && pathChar(keptLine[j]))
                ++j;
            std::string token = keptLine.substr(i, j - i);
            const char before = i > 0 ? keptLine[i - 1] : ' ';
            const bool variable = before == '$' || before == '@' || before == '{' || before == '}';
            while (!token.empty() && token.back() == '.')
                token.pop_back();
            if (!variable && projectPath(token)) {
                ++checked;
                if (!resolves(rel, token)) out.push_back({n, token});
            }
            i = j;
        }
    }
    return out;
}
} // namespace

TEST(CommentPaths, EveryProjectPathTheSourcesNameExists) {
    const std::vector<std::string> files = scannedFiles();
    ASSERT_GT(files.size(), 300u);
    int checked = 0;
    std::string stale;
    int count = 0;
    for (const auto& rel : files)
        for (const Finding& f : stalePaths(rel, slurp(kRoot / rel), checked)) {
            stale += "\n  " + rel + ":" + std::to_string(f.line) + ": " + f.token;
            ++count;
        }
    std::printf("%zu files, %d project paths named, %d that do not exist\n", files.size(), checked, count);
    EXPECT_GT(checked, 1000); // the scan sees the includes and the paths in comments
    EXPECT_EQ(count, 0) << "paths named in the sources that do not exist:" << stale;
}

TEST(CommentPaths, TheRuleFlagsProjectPathsOnly) {
    const std::string text =
        "#include \"util/no_such_header.h\"\n"
        "#include <vector>\n"
        "#include \"util/files.h\"\n"
        "// see renderer/util/no_such_file.h and util/files.h\n"
        "// https://example.org/renderer/gone.h, $OUT/results.json, out/results.json,\n"
        "// ../shared/scenes/gone/README.md, shaders/techniques/NAME.h, docs/no_such_page.md.\n"
        "int x = 0; // results.json\n"
        "const char* s = \"renderer/util/gone_too.cpp\";\n";
    int checked = 0;
    std::vector<std::string> found;
    for (const Finding& f : stalePaths("renderer/util/example.cpp", text, checked))
        found.push_back(std::to_string(f.line) + ":" + f.token);
    EXPECT_EQ(found, (std::vector<std::string>{"1:util/no_such_header.h", "4:renderer/util/no_such_file.h",
                                               "6:docs/no_such_page.md", "8:renderer/util/gone_too.cpp"}));
    EXPECT_EQ(checked, 6);
    // In tests/ a string literal is a fixture the test writes, not a path of the project.
    EXPECT_TRUE(stalePaths("tests/cpu/example.cpp", "auto p = \"renderer/util/gone.h\";\n", checked).empty());
}

namespace {
// A measured timing: a block of comment lines (a trailing comment and the whole-line comments
// under it, or a run of whole-line comments) that says it measured something (llvmpipe, took,
// faster, median, A/B, ...) and quotes a time (12 ms, 0.3 s) or a change (40 -> 34), or that
// quotes a percentage beside llvmpipe, faster, slower, measured or a run; or any line with a
// change in a time unit (15.0 -> 4.2 ms). Text in double quotes (an output's example) is not.
const std::regex kSays(
    R"(\b(measured|llvmpipe|faster|slower|took|takes?|costs?|saves?|saved|median|A/B|alternating|runs?)\b)",
    std::regex::icase);
const std::regex kSaysPercent(R"(\b(llvmpipe|faster|slower|measured|runs?)\b)", std::regex::icase);
const std::regex kTime(R"(\b\d+(\.\d+)?\s?(ms|us|µs|s|seconds)\b)");
const std::regex kChange(R"(\d\s?(->|→)\s?-?\d)");
const std::regex kPercent(R"(\d\s?%)");
const std::regex kQuoted(R"("[^"]*")");

// The lines of `block` (line number, text) that quote a measured timing.
void flagBlock(const std::vector<std::pair<int, std::string>>& block, std::vector<int>& out) {
    bool says = false, saysPercent = false;
    for (const auto& l : block) {
        says = says || std::regex_search(l.second, kSays);
        saysPercent = saysPercent || std::regex_search(l.second, kSaysPercent);
    }
    for (const auto& [n, text] : block) {
        const bool time = std::regex_search(text, kTime), change = std::regex_search(text, kChange);
        if ((says && (time || change)) || (saysPercent && std::regex_search(text, kPercent)) ||
            (time && change))
            out.push_back(n);
    }
}

std::vector<int> timedCommentLines(const std::string& text) {
    std::vector<int> out;
    std::stringstream lines(text), comments(commentsAndStrings(text, false));
    std::vector<std::pair<int, std::string>> block;
    std::string line, comment;
    for (int n = 1; std::getline(lines, line) && std::getline(comments, comment); ++n) {
        comment = std::regex_replace(comment, kQuoted, "");
        const size_t start = line.find_first_not_of(" \t");
        const bool blank = comment.find_first_not_of(' ') == std::string::npos;
        const bool trailing = !blank && start != std::string::npos && line.compare(start, 2, "//") != 0 &&
                              line.compare(start, 2, "/*") != 0 && line[start] != '*';
        if (blank || trailing) {
            flagBlock(block, out);
            block.clear();
        }
        if (!blank) block.push_back({n, comment});
    }
    flagBlock(block, out);
    return out;
}
} // namespace

TEST(CommentTimings, NoCommentOrHelpQuotesAMeasuredTiming) {
    std::string found;
    int files = 0;
    for (const auto& rel : scannedFiles()) {
        if (!cLike(rel) || rel.compare(0, 6, "tests/") == 0) continue;
        ++files;
        const std::string text = slurp(kRoot / rel);
        std::stringstream lines(text);
        std::vector<std::string> all;
        for (std::string l; std::getline(lines, l);)
            all.push_back(l);
        for (int n : timedCommentLines(text))
            found += "\n  " + rel + ":" + std::to_string(n) + ": " + all[size_t(n - 1)];
    }
    for (const ssao::Param& p : ssao::paramTable())
        if (!timedCommentLines("// " + p.help + "\n").empty())
            found += "\n  help of " + p.key + ": " + p.help;
    EXPECT_GT(files, 300);
    EXPECT_TRUE(found.empty()) << "comments and help that quote a timing measured on one machine (say why "
                                  "in a line and name the page that measures it, docs/bench/*.md):"
                               << found;
}

TEST(CommentTimings, TheRuleFlagsMeasurementsNotUnits) {
    const std::string text =
        "// One select rather than a branch: llvmpipe runs every side (measured:\n"
        "// 73.7 -> 61.9 ms, one A/B run).\n"
        "float x; // composite pass 15.0-18.0 -> 4.2-5.8 ms\n"
        "bool p; // off: it cost 9-13 % on llvmpipe\n"
        "int ms = 16; // a frame's budget, in ms\n"
        "int keep = 75; // levels that keep at most 75 % of the triangles save too little\n"
        "// \"0.47x the baseline's time (1.03 ms)\": the ratios first, as the plot reads.\n"
        "double p05; // the darkest 5 % of pixels\n"
        "double p50; // median\n"
        "// llvmpipe spends ~0.2 us per triangle (121k: ~27 ms of a drag frame).\n";
    EXPECT_EQ(timedCommentLines(text), (std::vector<int>{2, 3, 4, 10}));
}
