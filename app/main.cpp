// ssaolab command line: `render` (headless), `params` (the parameter table).
#include "render_command.h"
#include "scene/builtin_scenes.h"
#include "settings/params.h"
#include "util/error.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>

namespace {

void printParams() {
    std::printf("%-26s %-10s %-12s %-22s %s\n", "key", "default", "unit", "range", "what it does");
    for (const auto& p : ssao::paramTable()) {
        std::string range;
        if (p.type == ssao::Param::Type::Enum) {
            for (auto& c : p.choices) range += (range.empty() ? "" : "|") + c;
        } else if (p.type == ssao::Param::Type::Bool) {
            range = "true|false";
        } else {
            range = "[" + p.format(p.min) + ", " + p.format(p.max) + "]";
        }
        std::printf("%-26s %-10s %-12s %-22s %s\n", p.key.c_str(), p.format(p.def).c_str(), p.unit.c_str(),
                    range.c_str(), p.help.c_str());
    }
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"ssaolab — explore screen-space ambient occlusion: every parameter, every buffer, measured.\n"
                 "Without a subcommand it renders the default scene headless into ./out/."};
    app.require_subcommand(0, 1);
    ssao::RenderOptions ro;
    CLI::App* render = app.add_subcommand("render", "render a scene headless (EGL) into EXR/PNG buffers and metrics.json");
    ssao::addRenderOptions(*render, ro);
    app.add_subcommand("params", "list every parameter: key, default, unit, range, help");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (app.got_subcommand("params")) {
            printParams();
            return 0;
        }
        if (!app.got_subcommand("render") && std::getenv("DISPLAY"))
            std::fprintf(stderr, "ssaolab: the window app is not built yet; rendering headless into %s/\n", ro.out.c_str());
        return ssao::runRender(ro);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssaolab: error: %s\n", e.what());
        return 1;
    }
}
