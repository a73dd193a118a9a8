// ssaolab command line: `view` (window), `render` (headless), `params` (the parameter table).
// Without a subcommand: the window when there is a display, else a headless render into out/.
#include "cli/cli_util.h"
#include "cli/shared_options.h"
#include "cli/compile_gate.h"
#include "cli/headless_runner.h"
#include "cli/scene_options.h"
#include "cli/user_techniques.h"
#include "commands/bench/bench_command.h"
#include "commands/docs/cli_reference.h"
#include "commands/merge/merge_command.h"
#include "commands/probe/probe_command.h"
#include "commands/render/render_command.h"
#include "commands/skips/skips_command.h"
#include "commands/stress/stress_command.h"
#include "commands/tune/tune_command.h"
#include "scene/load/builtin_scenes.h"
#include "scene/scene.h"
#include "settings/params.h"
#include "settings/preset_store.h"
#include "techniques/technique.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/paths.h"
#include "view/app/window_app.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// The "default" column is what a run gets with nothing set: the start preset (render, view and the
// no-display run all begin there); "base" is the table's own value, what a preset file's keys patch.
void printParams() {
    const ssao::Settings start = ssao::PresetStore::standard().open(ssao::kStartPreset).settings;
    std::printf("Values with no preset: the start preset %s. A preset file sets keys over the base values "
                "(shown where they differ).\n\n",
                ssao::kStartPreset);
    std::printf("%-26s %-10s %-12s %-30s %s\n", "key", "default", "unit", "range", "what it does");
    for (const auto& p : ssao::paramTable()) {
        std::string range;
        if (p.type == ssao::Param::Type::Enum) {
            for (auto& c : p.choices)
                range += (range.empty() ? "" : "|") + c;
        } else if (p.type == ssao::Param::Type::Bool) {
            range = "true|false";
        } else {
            range = "[" + p.format(p.min) + ", " + p.format(p.max) + "]";
        }
        const std::string value = p.format(p.get(start)), base = p.format(p.def);
        std::printf("%-26s %-10s %-12s %-30s %s%s%s\n", p.key.c_str(), value.c_str(), p.unit.c_str(), range.c_str(),
                    p.help.c_str(), p.when.empty() ? "" : (" [applies when " + p.whenText() + "]").c_str(),
                    value == base ? "" : (" [base " + base + "]").c_str());
    }
}

// `ssaolab techniques` (hidden, for .ci/ scripts): the ids, one a line; with --levels the quality
// levels `make presets` tunes (ID LEVEL ROWS TUNED) and with --derived the presets that follow them
// (ID NAME FROM ROWS); lists comma-joined, "-" when empty.
void printTechniques(bool levels, bool derived) {
    auto joined = [](const std::vector<std::string>& v) {
        std::string out;
        for (const auto& s : v)
            out += (out.empty() ? "" : ",") + s;
        return out.empty() ? std::string("-") : out;
    };
    for (const auto& t : ssao::techniques()) {
        if (!levels && !derived) std::printf("%s\n", t.id.c_str());
        if (levels)
            for (const auto& l : t.levels)
                std::printf("%s %s %s %s\n", t.id.c_str(), l.name.c_str(), joined(l.set).c_str(), joined(t.tuned).c_str());
        if (derived)
            for (const auto& d : t.derived)
                std::printf("%s %s %s %s\n", t.id.c_str(), d.name.c_str(), d.from.c_str(), joined(d.set).c_str());
    }
}

// Every subcommand's options, parsed into one place.
struct Commands {
    CLI::App app{"ssaolab — explore screen-space ambient occlusion: every parameter, every buffer, measured.\n"
                 "Without a subcommand it opens the window (or, with no display, renders the default scene\n"
                 "headless into ./out/)."};
    double maxTriangles = double(ssao::SceneBudget{}.triangles);
    double maxSceneMib = double(ssao::SceneBudget{}.bytes >> 20);
    double maxMaskMpix = double(ssao::SceneBudget{}.maskPixels >> 20);
    std::string transparent = "skip";
    double frameTimeLimit = ssao::HeadlessRunner::kDefaultFrameTimeLimit;
    std::string techniqueDir;
    ssao::RenderOptions render;
    ssao::BenchOptions bench;
    ssao::BenchMergeOptions benchMerge;
    CLI::App* benchCmd = nullptr;
    ssao::TuneOptions tune;
    ssao::SkipsOptions skips;
    ssao::StressOptions stress;
    ssao::WindowOptions window;
    std::string windowSize = "1600x900", viewProjection, viewDepth;
    std::string docsPage, probeFile, probeSize = "64x36", childSource, compileVert = "passes/fullscreen.vert", compileShaders;
    std::vector<std::string> compileDefines;
    unsigned childMaxMib = 0;
    bool techniqueLevels = false, techniqueDerived = false;

    Commands() {
        app.require_subcommand(0, 1);
        app.fallthrough(); // global options may follow the subcommand
        app.allow_extras(); // mistyped options and commands are reported by refuseExtras, by name
        app.add_option("--max-triangles", maxTriangles,
                       "refuse scenes that expand to more triangles once instances are flattened")
            ->capture_default_str()
            ->check(ssao::cliRange(1.0, 2e9));
        app.add_option("--transparent", transparent,
                       "BLEND and transmissive glTF surfaces: skip (default: as engines draw them after the AO, "
                       "neither in the G-buffer nor occluding in the reference) or opaque (drawn and traced as solids)")
            ->capture_default_str()
            ->check(CLI::IsMember({"skip", "opaque"}));
        app.add_option("--max-scene-mib", maxSceneMib,
                       "refuse scenes whose buffers, or what they expand to, take more memory (MiB)")
            ->capture_default_str()
            ->check(ssao::cliRange(1.0, 1 << 20));
        app.add_option("--max-mask-mpix", maxMaskMpix,
                       "refuse scenes whose MASK materials' base-colour textures (the only images ssaolab decodes, for "
                       "their alpha cut-outs) hold more pixels in total (millions of 2^20), checked from each image's "
                       "header; for a web engine's browser (tune --engine, bench --engines) every image of the scene counts")
            ->capture_default_str()
            ->check(ssao::cliRange(1.0, 1 << 14));
        app.add_option("--frame-time-limit", frameTimeLimit,
                       "render, bench, tune, skips, stress: a frame whose GPU work takes longer (seconds) ends the "
                       "run with one error - a shader that never ends cannot hang it")
            ->capture_default_str()
            ->check(ssao::cliRange(0.01, 3600.0));
        app.add_option("--technique-dir", techniqueDir,
                       "the folder of your own techniques, NAME.ao.glsl each (docs/own-technique.md; default "
                       "$SSAOLAB_TECHNIQUE_DIR, else $XDG_CONFIG_HOME/ssaolab/techniques)")
            ->type_name(ssao::kInDir);
        ssao::addRenderOptions(*sub("render", "render a scene headless (EGL) into EXR/PNG buffers and metrics.json"),
                               render);
        benchCmd = sub("bench", "run time against error: every configuration of a sweep against the ray-traced reference");
        ssao::addBenchOptions(*benchCmd, bench);
        benchCmd->require_subcommand(0, 1);
        CLI::App* merge = benchCmd->add_subcommand(
            "merge", "join the output folders of `bench --shard K/N` runs into one run's results and reports");
        merge->allow_extras();
        ssao::addBenchMergeOptions(*merge, benchMerge);
        ssao::addTuneOptions(
            *sub("tune", "fit one technique's parameters to the ray-traced reference; report held-out views; save JSON"),
            tune);
        ssao::addSkipsOptions(*sub("skips", "work a scene does not need, skipped and measured: each skip against "
                                            "the same frame without it (dirty passes, sky, adaptive samples, "
                                            "culling, unused targets)"),
                              skips);
        ssao::addStressOptions(*sub("stress", "numerical stability: every technique under extreme projections, "
                                              "scales, placements, precisions and parameter limits; non-finite, "
                                              "out-of-range and invariance errors"),
                               stress);
        sub("params", "list every parameter: key, default, unit, range, help");
        sub("paths", "where this binary finds its shaders, assets and presets");
        app.add_subcommand("options", "every option of every command with its kind, as JSON lines (for tests)")
            ->group(""); // hidden: tests/cli/test_cli_paths.cpp takes the path options from it
        CLI::App* docs = app.add_subcommand("docs", "print a generated page of the manual (make docs)")->group(""); // hidden
        docs->add_option("page", docsPage, "commands or parameters")->required()->check(CLI::IsMember({"commands", "parameters"}));
        CLI::App* techs = app.add_subcommand("techniques", "the AO techniques' ids, one a line (for .ci/ scripts)")
                              ->group(""); // hidden
        techs->add_flag("--levels", techniqueLevels, "the quality levels make presets tunes: ID LEVEL ROWS TUNED");
        techs->add_flag("--derived", techniqueDerived, "the presets that follow tuned ones: ID NAME FROM ROWS");
        CLI::App* probe = app.add_subcommand("probe-technique", "render a user technique's file in two frames (the explorer's test)")
                              ->group(""); // hidden: app/view/live/technique_watch.h runs it
        probe->add_option("file", probeFile, "NAME.ao.glsl")->required()->type_name(ssao::kInFile);
        ssao::addSizeOption(*probe, probeSize);
        CLI::App* compile = app.add_subcommand("compile-glsl", "compile one program of an untrusted fragment shader (the compile gate's test)")
                                ->group(""); // hidden: app/cli/compile_gate.h runs it
        compile->add_option("name", probeFile, "the name the shader's errors carry")->required()->type_name("NAME");
        compile->add_option("--shaders", compileShaders, "the shader folder its includes come from")->type_name(ssao::kInDir);
        compile->add_option("--vert", compileVert, "the vertex shader, a file under the folder")->type_name("SHADER")->capture_default_str();
        compile->add_option("--define", compileDefines, "one define each")->type_name("NAME=VALUE");
        for (CLI::App* c : {probe, compile}) {
            c->add_option("--source", childSource, "the bytes to try (a file the parent wrote)")->type_name(ssao::kInFile);
            c->add_option("--max-memory-mib", childMaxMib, "cap this process's address space (MiB)")->check(ssao::cliRange(64, 1 << 20));
        }
        addView(*sub("view", "open the interactive explorer window (GLFW + Dear ImGui)"));
    }

    CLI::App* sub(const char* name, const char* help) {
        CLI::App* c = app.add_subcommand(name, help);
        c->allow_extras();
        return c;
    }

    void addView(CLI::App& view) {
        ssao::WindowOptions& wo = window;
        ssao::addSceneOption(view, wo.app.scene, {"", "default: the preset's scene, else builtin:showcase"});
        wo.app.preset = ssao::kStartPreset; // a new user's first frame: a point of the front (settings/preset.h)
        view.add_option("--preset", wo.app.preset, "preset name or JSON file")->type_name(ssao::kInFile)->capture_default_str();
        ssao::addShadersOption(view, wo.app.shaderDir, {"", "edits are hot-reloaded"});
        ssao::addPresetDirOption(view, wo.app.userPresetDir, {"", "the explorer's: $XDG_CONFIG_HOME/ssaolab/presets"});
        ssao::addSizeOption(view, windowSize, {"", "the window's, at least 200x150"});
        ssao::addLensOptions(view, viewProjection, viewDepth);
        ssao::addEngineModulesOption(view, wo.app.engineModules, {"", "for the Front tab"});
        view.add_option("--frames", wo.frames, "draw N frames then exit (for tests and screenshots)")
            ->check(ssao::cliRange(0, 1000000));
        view.add_option("--screenshot", wo.screenshot, "with --frames: save the last frame as PNG")->type_name(ssao::kOutFile);
        view.add_option("--frame-log", wo.frameLog, "write one line per drawn frame: ms, render size, moving, passes run")->type_name(ssao::kOutFile);
    }

    int runWindow() {
        ssao::WindowOptions& wo = window;
        ssao::parseSizeOption(windowSize, wo.width, wo.height); // strict, and within render's budget
        if (wo.width < 200 || wo.height < 150)
            throw ssao::Error("--size '" + windowSize + "': the window needs at least 200x150");
        if (!viewProjection.empty()) wo.app.projection = ssao::parseProjection(viewProjection);
        if (!viewDepth.empty()) wo.app.depth = ssao::parseDepthMode(viewDepth);
        if (!wo.screenshot.empty() && wo.frames <= 0)
            throw ssao::Error("--screenshot needs --frames N (the frame to save)");
        if (!wo.screenshot.empty()) ssao::checkOutputPath(wo.screenshot); // before the window opens
        return ssao::runWindowApp(wo);
    }

    int run() {
        ssao::setSceneBudget({size_t(maxTriangles), size_t(maxSceneMib) << 20, size_t(maxMaskMpix) << 20});
        ssao::setTransparentMode(ssao::parseTransparent(transparent));
        ssao::HeadlessRunner::setFrameTimeLimit(frameTimeLimit);
        // The generated pages and the option list describe the program, not this user's folder.
        if (app.got_subcommand("probe-technique")) {
            int w = 0, h = 0;
            ssao::parseSizeOption(probeSize, w, h);
            return ssao::runProbeTechnique(probeFile, childSource, w, h, childMaxMib);
        }
        if (app.got_subcommand("compile-glsl")) {
            if (childSource.empty()) throw ssao::Error("compile-glsl needs --source FILE");
            return ssao::runCompileGlsl(probeFile, childSource, compileShaders, compileVert, compileDefines, childMaxMib);
        }
        // Every other command compiles a user's GLSL after a child did: this very binary, even if the
        // file was replaced since it started.
        ssao::installCompileGate("/proc/self/exe");
        if (!app.got_subcommand("docs") && !app.got_subcommand("options"))
            window.app.techniqueDir = ssao::loadUserTechniques(techniqueDir);
        if (app.got_subcommand("params")) {
            printParams();
            return 0;
        }
        if (app.got_subcommand("docs")) {
            const std::string page = docsPage == "commands" ? ssao::commandReference(app) : ssao::parameterReference();
            std::fwrite(page.data(), 1, page.size(), stdout);
            return 0;
        }
        if (app.got_subcommand("techniques")) {
            printTechniques(techniqueLevels, techniqueDerived);
            return 0;
        }
        if (app.got_subcommand("options")) {
            ssao::printOptionKinds(app);
            return 0;
        }
        if (app.got_subcommand("paths")) {
            std::printf("binary     %s\ndata       %s (%s)\nshaders    %s\npresets    %s/presets, then %s\n"
                        "techniques %s\n",
                        ssao::executablePath().c_str(), ssao::dataRoot().c_str(), ssao::dataRootSource().c_str(),
                        ssao::shaderRoot().c_str(), ssao::assetRoot().c_str(),
                        ssao::PresetStore::defaultUserDir().c_str(), window.app.techniqueDir.c_str());
            for (const std::string& id : ssao::userTechniqueIds())
                std::printf("           %s (%s)\n", id.c_str(), ssao::findTechnique(id).file.c_str());
            if (window.app.techniqueDir.empty() || ssao::userTechniqueIds().empty())
                std::printf("           (none found: put NAME.ao.glsl files there, docs/own-technique.md)\n");
            return 0;
        }
        if (app.got_subcommand("bench"))
            return benchCmd->got_subcommand("merge") ? ssao::runBenchMerge(benchMerge) : ssao::runBench(bench);
        if (app.got_subcommand("tune")) return ssao::runTune(tune);
        if (app.got_subcommand("stress")) return ssao::runStress(stress);
        if (app.got_subcommand("skips")) return ssao::runSkips(skips);
        if (app.got_subcommand("view") || (!app.got_subcommand("render") && ssao::haveDisplay())) return runWindow();
        if (!app.got_subcommand("render")) {
            std::printf("no display: rendering headless into %s/ (for the window run `xvfb-run -a ssaolab` "
                        "or set DISPLAY)\n",
                        render.out.c_str());
            if (render.preset.empty()) render.preset = window.app.preset; // the window's first frame, headless
        }
        return ssao::runRender(render);
    }
};

// One line, whatever the message carries (a compiler log ends in a newline, may hold several).
int reportError(const std::string& what) {
    std::fprintf(stderr, "ssaolab: error: %s\n", ssao::oneLine(what).c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    Commands cli;
    try {
        cli.app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.app.exit(e); // --help
        // Like every other bad input: one line, exit code 1; the subcommand's own help.
        return reportError(std::string(e.what()) + " (see " + ssao::helpCommand(cli.app) + ")");
    }
    try {
        ssao::refuseExtras(cli.app);
        return cli.run();
    } catch (const std::exception& e) {
        return reportError(e.what());
    }
}
