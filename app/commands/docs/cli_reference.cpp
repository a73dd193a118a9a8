#include "commands/docs/cli_reference.h"

#include "output/escape.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "settings/preset_store.h"

#include <CLI/CLI.hpp>

#include <sstream>

namespace ssao {

namespace {

constexpr const char* kRegenerate = "Generated from the program's own definitions: regenerate with `make docs` "
                                    "(a test fails when this page is stale).";

// A code span in a table cell: backslash escapes do not work inside one, but GFM splits cells on a
// '|' even there unless it is written '\|'; a backtick inside takes a longer fence.
std::string code(const std::string& s) {
    if (s.empty()) return "";
    std::string t;
    for (char c : s)
        t += c == '|' ? std::string("\\|") : c == '\n' || c == '\r' ? std::string(" ") : std::string(1, c);
    const std::string fence = s.find('`') == std::string::npos ? "`" : "`` ";
    return fence + t + (fence == "`" ? "`" : " ``");
}

void optionTable(std::ostringstream& md, const CLI::App& cmd) {
    std::ostringstream rows;
    for (const CLI::Option* o : cmd.get_options()) {
        const std::string name = o->get_name(false, true);
        if (name.empty() || name == "-h,--help" || name == "--help" || o->get_group().empty()) continue;
        rows << "| " << code(name) << " | " << markdownCell(o->get_type_name()) << " | " << code(o->get_default_str()) << " | "
             << markdownCell(o->get_description()) << " |\n";
    }
    const std::string r = rows.str();
    if (r.empty()) return;
    md << "| option | value | default | what it does |\n|---|---|---|---|\n" << r << "\n";
}

void command(std::ostringstream& md, const CLI::App& cmd, const std::string& path) {
    md << "## `" << path << "`\n\n" << markdownCell(cmd.get_description()) << "\n\n";
    optionTable(md, cmd);
    for (const CLI::App* sub : cmd.get_subcommands({}))
        if (!sub->get_group().empty()) command(md, *sub, path + " " + sub->get_name());
}

} // namespace

std::string commandReference(const CLI::App& app) {
    std::ostringstream md;
    md << "# Commands\n\n" << kRegenerate << " `ssaolab COMMAND --help` prints the same.\n\n"
       << "Options before or after the command, for every command:\n\n";
    optionTable(md, app);
    for (const CLI::App* sub : app.get_subcommands({}))
        if (!sub->get_group().empty()) command(md, *sub, "ssaolab " + sub->get_name());
    return md.str();
}

std::string parameterReference() {
    const Settings start = PresetStore::standard().open(kStartPreset).settings;
    std::ostringstream md;
    md << "# Parameters\n\n" << kRegenerate << " `ssaolab params` prints the same table.\n\n"
       << "Every key works in the explorer, in presets (`{\"group\": {\"name\": value}}`) and as `--set key=value`. "
          "Defaults are the start preset `" << kStartPreset << "`'s (the first frame); *base* is the value a preset "
          "file sets keys over where it differs.\n\n"
       << "| key | default | unit | range | what it does | applies when |\n|---|---|---|---|---|---|\n";
    for (const auto& p : paramTable()) {
        std::string range;
        if (p.type == Param::Type::Enum) {
            for (const auto& c : p.choices)
                range += (range.empty() ? "" : " \\| ") + c;
        } else if (p.type == Param::Type::Bool) {
            range = "true \\| false";
        } else {
            range = "[" + p.format(p.min) + ", " + p.format(p.max) + "]";
        }
        const std::string value = p.format(p.get(start)), base = p.format(p.def);
        md << "| " << code(p.key) << " | " << code(value) << (value == base ? "" : " (base " + code(base) + ")") << " | "
           << markdownCell(p.unit) << " | " << range << " | " << markdownCell(p.help) << " | "
           << markdownCell(p.when.empty() ? "" : p.whenText()) << " |\n";
    }
    return md.str();
}

} // namespace ssao
