// report.html in a real browser (Debian's chromium, headless; .ci/install-deps.sh installs it):
// every image decodes, the plots are drawn, no script error. The page checks itself on load and
// writes the verdict into <body data-check=...>; --dump-dom prints the DOM after that.
#include "cli_run.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace ssaotest;

namespace {
std::string chromium(const std::string& args, const std::string& log) {
    // One profile per test process: Chromium refuses a profile another instance holds (ctest -j).
    const std::string profile = std::string(SSAOLAB_TEST_TMP) + "/chromium_profile_" + std::to_string(::getpid());
    const std::string cmd = "timeout 120 chromium --headless --no-sandbox --disable-gpu --no-first-run "
                            "--user-data-dir=" + profile + " --enable-logging=stderr --v=0 " + args + " >" + log +
                            ".out 2>" + log + ".err </dev/null";
    const int rc = std::system(cmd.c_str());
    EXPECT_EQ(rc, 0) << slurp(log + ".err");
    return slurp(log + ".out");
}
} // namespace

TEST(ReportHtml, OpensInARealBrowserWithEveryImageAndPlot) {
    ASSERT_EQ(std::system("command -v chromium >/dev/null"), 0)
        << "chromium is missing: .ci/install-deps.sh installs it (Debian package chromium)";
    const std::string out = outDir("report_html");
    std::filesystem::remove_all(out);
    const std::string sweep = writeTemp("html_sweep.json", R"({"name": "html", "groups": [{"name": "k", "vary": {"kernel.samples": [8, 64]}}]})");
    CliRun r = ssaolab("bench --scene builtin:showcase --scene " + std::string(SSAOLAB_SCENES_DIR) +
                       "/CornellBox/cornellBox.gltf --size 160x90 --views 2 --frames 2 --warmup 0 --reference-rays 8 "
                       "--no-plot --quiet --sweep " + sweep + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string log = std::string(SSAOLAB_TEST_TMP) + "/chromium_report";
    const std::string dom = chromium("--virtual-time-budget=5000 --dump-dom file://" + out + "/report.html", log);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(dom, m, std::regex("<body[^>]*data-check=\"([^\"]*)\"")))
        << "the page's own check never ran:\n" << dom.substr(0, 2000);
    EXPECT_EQ(m[1].str(), "ok");
    ASSERT_TRUE(std::regex_search(dom, m, std::regex("data-images=\"(\\d+)\"")));
    // Two references, then per front configuration and the baseline an AO and an error image per scene.
    EXPECT_GE(std::stoi(m[1].str()), 2 + 2 * 2);
    ASSERT_TRUE(std::regex_search(dom, m, std::regex("data-plots=\"(\\d+)\"")));
    EXPECT_EQ(m[1].str(), "3"); // all scenes, then one per scene
    // No console error or uncaught exception in the browser's own log either.
    const std::string err = slurp(log + ".err");
    EXPECT_EQ(err.find("Uncaught"), std::string::npos) << err;
    EXPECT_EQ(std::regex_search(err, std::regex("CONSOLE\\([0-9]+\\)\\].*[Ee]rror")), false) << err;
    // A screenshot, to look at (docs/report.png is one of these).
    chromium("--hide-scrollbars --window-size=1400,2000 --screenshot=" + out + "/report.png file://" + out +
                 "/report.html",
             log + "_shot");
    EXPECT_GT(std::filesystem::file_size(out + "/report.png"), 50000u);
}

namespace {
namespace fs = std::filesystem;

// Would leave a <xss-ran> element in the DOM if any name ever ran as script.
const std::string kRun = "document.body.appendChild(document.createElement('xss-ran'))";

// `s` as one word for sh -c.
std::string shq(const std::string& s) {
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// The unescaped | of one Markdown table line (a backslash escapes the character after it).
int pipes(const std::string& line) {
    int n = 0;
    for (size_t i = 0; i < line.size(); ++i)
        if (line[i] == '\\') ++i;
        else n += line[i] == '|';
    return n;
}

// Every table of a Markdown file: each row has its header's cells, and a blank line ends it.
void expectWholeMarkdownTables(const std::string& md, const std::string& file) {
    EXPECT_EQ(md.find('\r'), std::string::npos) << file;
    EXPECT_EQ(md.find("<img"), std::string::npos) << file;
    EXPECT_EQ(md.find("<svg"), std::string::npos) << file;
    std::vector<std::string> lines;
    std::istringstream in(md);
    for (std::string l; std::getline(in, l);)
        lines.push_back(l);
    int tables = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].rfind("|", 0) != 0) continue;
        ++tables;
        const int header = pipes(lines[i]);
        size_t j = i + 1;
        for (; j < lines.size() && lines[j].rfind("|", 0) == 0; ++j)
            EXPECT_EQ(pipes(lines[j]), header) << file << " line " << j + 1 << ": " << lines[j];
        if (j < lines.size()) {
            EXPECT_EQ(lines[j], "") << file << " line " << j + 1 << " continues a table row";
        }
        i = j;
    }
    EXPECT_GE(tables, 3) << file;
}

// RFC 4180 records; a CR or LF outside quotes ends a record, as spreadsheets read it.
std::vector<std::vector<std::string>> parseCsv(const std::string& s, const std::string& file) {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row;
    std::string field;
    bool quoted = false, any = false;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (quoted) {
            if (c != '"') field += c;
            else if (i + 1 < s.size() && s[i + 1] == '"') field += '"', ++i;
            else quoted = false;
        } else if (c == '"') {
            EXPECT_TRUE(field.empty()) << file << ": a quote inside an unquoted field: " << field;
            quoted = true, any = true;
        } else if (c == ',') {
            row.push_back(field), field.clear(), any = true;
        } else if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < s.size() && s[i + 1] == '\n') ++i;
            row.push_back(field), field.clear();
            rows.push_back(row), row.clear(), any = false;
        } else {
            field += c, any = true;
        }
    }
    EXPECT_FALSE(quoted) << file << ": an unterminated quote";
    if (any) row.push_back(field), rows.push_back(row);
    return rows;
}

// Every record has the header's columns; no text cell starts a spreadsheet formula.
std::vector<std::vector<std::string>> expectSafeCsv(const std::string& path) {
    const auto rows = parseCsv(slurp(path), path);
    EXPECT_GE(rows.size(), 2u) << path;
    if (rows.empty()) return rows;
    const std::set<std::string> text = {"scene", "viewpoint", "label", "technique", "shard", "settings"};
    for (size_t r = 1; r < rows.size(); ++r) {
        EXPECT_EQ(rows[r].size(), rows[0].size()) << path << " record " << r;
        for (size_t c = 0; c < rows[r].size() && c < rows[0].size(); ++c)
            if (text.count(rows[0][c]) && !rows[r][c].empty()) {
                EXPECT_EQ(std::string("=+-@\t\r").find(rows[r][c][0]), std::string::npos)
                    << path << " record " << r << " " << rows[0][c] << ": " << rows[r][c];
            }
    }
    return rows;
}

// report.html in the browser: its own check (images, plots, tables of one width, no error) says
// ok, and no name ran as script.
void expectSafeHtml(const std::string& dir, const std::string& tag) {
    const std::string log = std::string(SSAOLAB_TEST_TMP) + "/chromium_" + tag;
    const std::string dom = chromium("--virtual-time-budget=5000 --dump-dom file://" + dir + "/report.html", log);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(dom, m, std::regex("<body[^>]*data-check=\"([^\"]*)\"")))
        << "the page's own check never ran:\n" << dom.substr(0, 2000);
    EXPECT_EQ(m[1].str(), "ok") << tag;
    EXPECT_EQ(dom.find("<xss-ran"), std::string::npos) << tag << ": a name ran as script";
    EXPECT_EQ(slurp(log + ".err").find("Uncaught"), std::string::npos) << tag;
}

// Copies the cornell box to `dir`/`name` (its buffer beside it, as the glTF names it).
std::string sceneCopy(const fs::path& dir, const std::string& name) {
    fs::create_directories(dir);
    const fs::path src = fs::path(SSAOLAB_SCENES_DIR) / "CornellBox";
    fs::copy_file(src / "cornellBox.gltf", dir / name, fs::copy_options::overwrite_existing);
    fs::copy_file(src / "cornellBox.bin", dir / "cornellBox.bin", fs::copy_options::overwrite_existing);
    return (dir / name).string();
}

// `dir`'s run recast as two shards whose machine facts are hostile text, merged into `out`.
void mergeWithHostileMachine(const std::string& dir, const std::string& out, const std::string& evil) {
    const std::string in = dir + "_shards";
    fs::remove_all(in);
    fs::remove_all(out);
    fs::copy(dir, in, fs::copy_options::recursive);
    auto j = nlohmann::json::parse(slurp(in + "/results.json"));
    for (const char* k : {"cpu", "gl_renderer", "date", "git_revision"})
        j[k] = evil;
    nlohmann::json sh = j["shards"][0];
    for (const char* k : {"hostname", "cpu", "gl_renderer", "date", "git_revision"})
        sh[k] = evil;
    nlohmann::json second = sh;
    sh["shard"] = "1/2", second["shard"] = "2/2";
    j["shards"] = {sh, second};
    for (auto& r : j["results"]) // the second scene's rows (its baseline with them) to shard 2/2
        r["shard"] = r["scene"] == j["scenes"][0]["name"] ? 0 : 1;
    std::ofstream(in + "/results.json") << j.dump();
    CliRun r = ssaolab("bench merge " + in + " --no-plot --quiet --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
}
} // namespace

// Names from input (sweep, groups, preset paths in labels, scene files, the machine's facts)
// stay text: no script in report.html, whole tables in report.md, whole rows and no formula in
// the CSV files.
TEST(ReportHtml, HostileNamesStayTextInEveryReport) {
    ASSERT_EQ(std::system("command -v chromium >/dev/null"), 0);
    const fs::path t = fs::path(SSAOLAB_TEST_TMP) / "hostile_names";
    fs::remove_all(t);
    fs::create_directories(t);
    const std::string img = "<img src=x onerror=" + kRun + ">", svg = "<svg onload=" + kRun + ">";
    const std::string evil = img + "\" onload=\"" + kRun + "\" ' onload='" + kRun + "' | a\nb\rc =HYPERLINK(\"x\")";
    const std::string scene1 = sceneCopy(t, "@SUM(1)|" + img + "'.gltf");
    const std::string scene2 = sceneCopy(t, "=HYPERLINK(\"x\")\r\n\" onload=\"" + kRun + "\".gltf");
    // Preset files named by relative paths (the run's folder is `t`): they become labels.
    const std::string baseline = "-1 " + svg + "|.json", groupPreset = "+1\n' onload='" + kRun + "'.json";
    fs::copy_file(fs::path(SSAOLAB_ASSET_DIR) / "presets/learnopengl.json", t / baseline);
    fs::copy_file(fs::path(SSAOLAB_ASSET_DIR) / "presets/gtao-low.json", t / groupPreset);
    nlohmann::json sweep = {{"name", evil}, {"groups", nlohmann::json::array()}};
    sweep["groups"].push_back({{"name", "=HYPERLINK(\"x\")|" + img + "\r\n"}, {"vary", {{"kernel.samples", {8}}}}});
    sweep["groups"].push_back({{"name", "@SUM(1)' onload='" + kRun + "'\n+1 -1 `x|y`"}, {"preset", groupPreset}});
    std::ofstream(t / "sweep.json") << sweep.dump();
    const std::string out = (t / "out").string();
    CliRun r = ssaolab("bench --scene " + shq(scene1) + " --scene " + shq(scene2) + " --baseline=" + shq(baseline) +
                           " --size 160x90 --views 1 --frames 2 --warmup 0 --reference-rays 8 --no-plot --quiet "
                           "--sweep sweep.json --out " + out,
                       "cd " + shq(t.string()) + " &&");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string merged = (t / "merged").string();
    mergeWithHostileMachine(out, merged, evil);
    for (const std::string& dir : {out, merged}) {
        SCOPED_TRACE(dir);
        expectWholeMarkdownTables(slurp(dir + "/report.md"), dir + "/report.md");
        const auto results = expectSafeCsv(dir + "/results.csv");
        expectSafeCsv(dir + "/summary.csv");
        // The scene's name survives, neutralised, as one cell.
        std::set<std::string> scenes;
        for (size_t i = 1; i < results.size(); ++i)
            scenes.insert(results[i][0]);
        EXPECT_TRUE(scenes.count("'@SUM(1)|" + img + "'")) << *scenes.begin();
        expectSafeHtml(dir, fs::path(dir).filename().string());
    }
}
