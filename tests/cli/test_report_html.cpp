// report.html in a real browser (Debian's chromium, headless; .ci/install-deps.sh installs it):
// every image decodes, the plots are drawn, no script error. The page checks itself on load and
// writes the verdict into <body data-check=...>; --dump-dom prints the DOM after that.
#include "cli_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

using namespace ssaotest;

namespace {
std::string chromium(const std::string& args, const std::string& log) {
    const std::string profile = std::string(SSAOLAB_TEST_TMP) + "/chromium_profile";
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
