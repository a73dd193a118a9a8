#include "cli/shared_options.h"

#include "cli/cli_util.h"

#include <CLI/CLI.hpp>

#include <cmath>

namespace ssao {

namespace {

std::string words(const OptionWords& w, const std::string& help) {
    return w.context + help + (w.note.empty() ? "" : " (" + w.note + ")");
}

} // namespace

CLI::Option* addSceneOption(CLI::App& cmd, std::string& scene, const OptionWords& w) {
    return cmd.add_option("--scene", scene, words(w, "builtin:NAME (showcase, plane, corner, slabs, hidden) or a .gltf/.glb file"))
        ->type_name(kInFile);
}

CLI::Option* addSceneOption(CLI::App& cmd, std::vector<std::string>& scenes, const OptionWords& w) {
    return cmd.add_option("--scene", scenes,
                          words(w, "builtin:NAME (showcase, plane, corner, slabs, hidden) or a .gltf/.glb file; repeatable"))
        ->type_name(kInFile);
}

CLI::Option* addSizeOption(CLI::App& cmd, std::string& size, const OptionWords& w) {
    return cmd.add_option("--size", size, words(w, "render size WIDTHxHEIGHT"))->type_name("WxH")->capture_default_str();
}

CLI::Option* addViewsOption(CLI::App& cmd, int& views, const OptionWords& w) {
    return cmd.add_option("--views", views, words(w, "viewpoints per scene: its camera (or --camera), then orbits about it"))
        ->capture_default_str()
        ->check(cliRange(1, 32));
}

CLI::Option* addTimedFramesOption(CLI::App& cmd, int& frames, const OptionWords& w) {
    return cmd.add_option("--frames", frames, words(w, "timed frames (median)"))->capture_default_str()->check(cliRange(1, 10000));
}

CLI::Option* addTimingFramesOption(CLI::App& cmd, int& frames, const OptionWords& w) {
    return cmd.add_option("--timing-frames", frames, words(w, "frames a time is measured over"))
        ->capture_default_str()
        ->check(cliRange(1, 100)); // each may be a whole frame with every pass forced: minutes past 100
}

CLI::Option* addRadiusSceneOption(CLI::App& cmd, float& radius, const OptionWords& w) {
    return cmd.add_option("--radius-scene", radius,
                          words(w, "the AO radius R as a fraction of the scene's bounding-box diagonal"))
        ->capture_default_str()
        ->check(cliRange(0.0001, 0.5));
}

CLI::Option* addSetOption(CLI::App& cmd, std::vector<std::string>& sets, const OptionWords& w) {
    return cmd.add_option("--set", sets, words(w, "one parameter, KEY=VALUE, e.g. gtao.steps=4 (repeatable; see `ssaolab params`)"))
        ->type_name("KEY=VALUE");
}

CLI::Option* addReferenceRaysOption(CLI::App& cmd, int& rays, const OptionWords& w) {
    return cmd.add_option("--reference-rays", rays, words(w, "reference rays per pixel"))
        ->capture_default_str()
        ->check(cliRange(1, 1 << 16));
}

CLI::Option* addReferenceVariantOption(CLI::App& cmd, std::string& variant, const OptionWords& w) {
    return cmd.add_option("--reference-variant", variant,
                          words(w, "visibility (XeGTAO's: binary within R) or obscurance (linear falloff 1 - t/R)"))
        ->capture_default_str()
        ->check(CLI::IsMember({"visibility", "obscurance"}));
}

void addOracleOptions(CLI::App& cmd, int& layers, double& thickness, int& guard, const OptionWords& w) {
    cmd.add_option("--oracle-layers", layers,
                   words(w, "depth layers of the screen-space oracle's G-buffer (2: a deep G-buffer; at least 2 when the "
                            "settings read gbuffer.second_layer)"))
        ->capture_default_str()
        ->check(cliRange(1, 2));
    cmd.add_option("--oracle-thickness", thickness,
                   words(w, "thickness of the oracle's surfaces, x R (inf: a height field, GTAO's assumption)"))
        ->capture_default_str()
        ->check(cliRange(1e-3, INFINITY));
    cmd.add_option("--oracle-guard", guard, words(w, "pixels the oracle's G-buffer holds beyond each edge of the frame"))
        ->capture_default_str()
        ->check(cliRange(0, 4096));
}

CLI::Option* addShadersOption(CLI::App& cmd, std::string& dir, const OptionWords& w) {
    return cmd.add_option("--shaders", dir, words(w, "shader folder (default: the installed or source tree's shaders/)"))
        ->type_name(kInDir);
}

CLI::Option* addPresetDirOption(CLI::App& cmd, std::string& dir, const OptionWords& w) {
    return cmd.add_option("--preset-dir", dir, words(w, "folder of user presets (default: as the app)"))->type_name(kInDir);
}

CLI::Option* addEngineModulesOption(CLI::App& cmd, std::string& dir, const OptionWords& w) {
    return cmd.add_option("--engine-modules", dir,
                          words(w, "the web engines' npm packages (default: the build folder's peers/node_modules, from "
                                   "make engine-modules)"))
        ->type_name(kInDir);
}

CLI::Option* addBudgetMsOption(CLI::App& cmd, double& ms, const OptionWords& w) {
    return cmd.add_option("--budget-ms", ms, words(w, "a time budget, ms"))->type_name("MS")->check(cliRange(1e-6, 1e6));
}

CLI::Option* addBudgetRatioOption(CLI::App& cmd, double& ratio, const OptionWords& w) {
    return cmd.add_option("--budget-ratio", ratio, words(w, "a time budget as a multiple of the baseline's time"))
        ->type_name("X")
        ->check(cliRange(1e-6, 1e6));
}

CLI::Option* addMaxErrorOption(CLI::App& cmd, double& maxError, const OptionWords& w) {
    return cmd.add_option("--max-error", maxError,
                          words(w, "answer: the fastest configuration whose error (RMSE, or the motion score with "
                                   "--objective motion) is at most this"))
        ->type_name("RMSE")
        ->check(cliRange(1e-9, 1.0));
}

CLI::Option* addObjectiveOption(CLI::App& cmd, std::string& objective, const OptionWords& w) {
    return cmd.add_option("--objective", objective, words(w, "still (the still frame's RMSE) or motion (the motion score along each view's camera path)"))
        ->capture_default_str()
        ->check(CLI::IsMember({"still", "motion"}));
}

CLI::Option* addQuietFlag(CLI::App& cmd, bool& quiet, const OptionWords& w) {
    return cmd.add_flag("--quiet", quiet, words(w, "no progress output"));
}

CLI::Option* addNoPlotFlag(CLI::App& cmd, bool& plot) {
    return cmd.add_flag("--no-plot", [&plot](int64_t) { plot = false; }, "skip the matplotlib plot");
}

} // namespace ssao
