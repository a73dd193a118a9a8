// The manual's generated pages match the program: docs/commands.md is every command and option as
// the command line defines them, docs/parameters.md the parameter table (`make docs` regenerates
// both); and every page the README links to exists.
#include "cli_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

using namespace ssaotest;
namespace fs = std::filesystem;

TEST(Docs, TheGeneratedPagesAreCurrent) {
    for (const char* page : {"commands", "parameters"}) {
        const CliRun r = ssaolab(std::string("docs ") + page);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::string file = std::string(SSAOLAB_SOURCE_DIR) + "/docs/" + page + ".md";
        EXPECT_EQ(slurp(file), r.out) << file << " is stale: run `make docs` and commit it";
    }
    const std::string commands = slurp(std::string(SSAOLAB_SOURCE_DIR) + "/docs/commands.md");
    for (const char* cmd : {"## `ssaolab render`", "## `ssaolab bench`", "## `ssaolab bench merge`", "## `ssaolab tune`",
                            "## `ssaolab view`", "`--engines`", "`--budget-ratio`"})
        EXPECT_NE(commands.find(cmd), std::string::npos) << cmd;
    EXPECT_EQ(commands.find("## `ssaolab options`"), std::string::npos) << "hidden commands stay out of the manual";
}

TEST(Docs, EveryPageTheManualLinksToExists) {
    const fs::path root(SSAOLAB_SOURCE_DIR);
    std::vector<fs::path> pages = {root / "README.md"};
    for (const auto& e : fs::recursive_directory_iterator(root / "docs"))
        if (e.path().extension() == ".md") pages.push_back(e.path());
    const std::regex link(R"re(\]\(([^)#\s]+)(#[^)\s]*)?\))re");
    for (const fs::path& page : pages) {
        const std::string text = slurp(page.string());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
            const std::string target = (*it)[1];
            if (target.rfind("http", 0) == 0) continue;
            EXPECT_TRUE(fs::exists(page.parent_path() / target)) << page.lexically_relative(root) << " links to " << target;
        }
    }
}

TEST(Docs, TheReadmeIsAManualOfAtMost250Lines) {
    const std::string readme = slurp(std::string(SSAOLAB_SOURCE_DIR) + "/README.md");
    EXPECT_LE(std::count(readme.begin(), readme.end(), '\n'), 250);
    for (const char* diary : {"latest run", "this session", "earlier runs", "run of 20"})
        EXPECT_EQ(readme.find(diary), std::string::npos) << "the README tells a story: '" << diary << "'";
}

// An option several commands take is declared once (app/cli/shared_options.h): its value type and
// range read the same in every command of the manual. Two names stay apart on purpose: --out is each
// command's own output (a folder, or tune's JSON file), and the explorer's --frames counts frames
// drawn before it exits, not timed ones.
TEST(Docs, ASharedOptionReadsTheSameInEveryCommand) {
    const CliRun r = ssaolab("docs commands");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::regex heading(R"(^## `ssaolab ([a-z -]+)`)"), row(R"(^\| `(--[a-z0-9-]+)` \| ([^|]*) \|)");
    std::map<std::string, std::map<std::string, std::string>> seen; // option -> command -> value column
    std::string command, line;
    std::istringstream in(r.out);
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, heading)) command = m[1];
        else if (!command.empty() && std::regex_search(line, m, row)) seen[m[1]][command] = m[2];
    }
    int shared = 0;
    for (const auto& [option, commands] : seen) {
        if (commands.size() < 2 || option == "--out") continue;
        ++shared;
        std::string first;
        for (const auto& [cmd, value] : commands) {
            if (option == "--frames" && cmd == "view") continue;
            if (first.empty()) first = value;
            EXPECT_EQ(value, first) << option << " in `ssaolab " << cmd << "`";
        }
    }
    EXPECT_GE(shared, 20) << "the shared options the manual lists";
    EXPECT_EQ(seen["--oracle-guard"]["bench"], seen["--oracle-guard"]["render"]);
}
