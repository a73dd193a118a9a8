#include "cli/cli_util.h"

#include "util/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ssao {

CLI::Validator cliRange(double lo, double hi) {
    const std::string desc = "[" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]";
    return CLI::Validator(
        [lo, hi](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
            // +inf only where the range is open above (a thickness may be infinite); NaN never.
            if (!std::isfinite(v) && !(v > 0 && std::isinf(v) && std::isinf(hi)))
                return "'" + text + "' is not a finite number";
            if (v < lo || v > hi) return "'" + text + "' is outside [" + CLI::detail::to_string(lo) + ", " +
                                         CLI::detail::to_string(hi) + "]";
            return {};
        },
        desc, "RANGE");
}

namespace {
// The innermost subcommand chosen ("bench merge"), else the program itself.
const CLI::App* chosen(const CLI::App& app) {
    const CLI::App* cmd = &app;
    for (auto subs = cmd->get_subcommands(); !subs.empty(); subs = cmd->get_subcommands())
        cmd = subs.back();
    return cmd;
}
// "bench merge" for that subcommand, "" for the program.
std::string commandPath(const CLI::App* cmd) {
    std::string path;
    for (; cmd && cmd->get_parent(); cmd = cmd->get_parent())
        path = cmd->get_name() + (path.empty() ? "" : " " + path);
    return path;
}
} // namespace

std::string helpCommand(const CLI::App& app) {
    const std::string path = commandPath(chosen(app));
    return path.empty() ? "ssaolab --help" : "ssaolab " + path + " --help";
}

void refuseExtras(const CLI::App& app) {
    const CLI::App* cmd = chosen(app);
    std::vector<std::string> extras = cmd->remaining();
    for (const CLI::App* up = cmd->get_parent(); extras.empty() && up; up = up->get_parent())
        extras = up->remaining();
    if (extras.empty()) return;
    const std::string& first = extras.front();
    const std::string help = helpCommand(app);
    const std::string name = commandPath(cmd);
    if (first.empty() || first[0] != '-') {
        std::vector<std::string> names;
        for (const CLI::App* sub : cmd->get_subcommands({}))
            names.push_back(sub->get_name());
        if (cmd != &app && names.empty())
            throw Error(name + ": unexpected argument '" + first + "' (see " + help + ")");
        if (cmd != &app)
            throw Error(name + ": unexpected argument '" + first + "'" +
                        (closestName(first, names).empty() ? "" : " (did you mean " + closestName(first, names) + "?)") +
                        " (see " + help + ")");
        const std::string near = closestName(first, names);
        throw Error("unknown command '" + first + "'" + (near.empty() ? "" : " (did you mean " + near + "?)") +
                    " (see ssaolab --help)");
    }
    std::vector<std::string> names;
    for (const CLI::Option* o : cmd->get_options())
        for (const auto& n : o->get_lnames())
            names.push_back("--" + n);
    const std::string word = first.substr(0, first.find('='));
    const std::string near = closestName(word, names);
    throw Error((cmd == &app ? std::string() : name + ": ") + "unknown option '" + word + "'" +
                (near.empty() ? "" : " (did you mean " + near + "?)") + " (see " + help + ")");
}

namespace {
void printCommandOptions(const CLI::App& cmd, const std::string& path) {
    for (const CLI::Option* opt : cmd.get_options()) {
        if (opt->get_name() == "--help") continue;
        const nlohmann::json line = {{"command", path},
                                     {"option", opt->get_name()},
                                     {"type", opt->get_type_name()},
                                     {"flag", opt->get_expected_min() == 0}};
        std::printf("%s\n", line.dump().c_str());
    }
    for (const CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; }))
        printCommandOptions(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name());
}
} // namespace

void printOptionKinds(const CLI::App& app) {
    printCommandOptions(app, "");
}

void printWarnings(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings)
        std::fprintf(stderr, "ssaolab: warning: %s\n", oneLine(w).c_str());
}

} // namespace ssao
