// The options several commands take, each declared once here - its name, value type, range and
// the words of its help - and composed by the commands that take it. A command adds only what is
// its own: a context ("with --reference: ") or a note on its default. docs/commands.md then shows
// each the same wherever it appears (test Docs.ASharedOptionReadsTheSameInEveryCommand).
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace ssao {

// What a command adds to a shared option's help: `context` before it, `note` after it in brackets.
struct OptionWords {
    std::string context, note;
};

// --scene: one scene, or several (repeatable).
CLI::Option* addSceneOption(CLI::App& cmd, std::string& scene, const OptionWords& w = {});
CLI::Option* addSceneOption(CLI::App& cmd, std::vector<std::string>& scenes, const OptionWords& w = {});
// --size WIDTHxHEIGHT (parseSizeOption reads it).
CLI::Option* addSizeOption(CLI::App& cmd, std::string& size, const OptionWords& w = {});
// --views: viewpoints per scene, [1, 32].
CLI::Option* addViewsOption(CLI::App& cmd, int& views, const OptionWords& w = {});
// --frames: timed frames (median), [1, 10000].
CLI::Option* addTimedFramesOption(CLI::App& cmd, int& frames, const OptionWords& w = {});
// --timing-frames: frames a time is measured over, [1, 100].
CLI::Option* addTimingFramesOption(CLI::App& cmd, int& frames, const OptionWords& w = {});
// --radius-scene: R as a fraction of the scene's diagonal, [0.0001, 0.5].
CLI::Option* addRadiusSceneOption(CLI::App& cmd, float& radius, const OptionWords& w = {});
// --set KEY=VALUE (repeatable): one parameter of the settings.
CLI::Option* addSetOption(CLI::App& cmd, std::vector<std::string>& sets, const OptionWords& w = {});
// --reference-rays and --reference-variant: the ray-traced reference.
CLI::Option* addReferenceRaysOption(CLI::App& cmd, int& rays, const OptionWords& w = {});
CLI::Option* addReferenceVariantOption(CLI::App& cmd, std::string& variant, const OptionWords& w = {});
// --oracle-layers, --oracle-thickness, --oracle-guard: the screen-space oracle's G-buffer.
void addOracleOptions(CLI::App& cmd, int& layers, double& thickness, int& guard, const OptionWords& w = {});
// --shaders, --preset-dir, --engine-modules: folders read.
CLI::Option* addShadersOption(CLI::App& cmd, std::string& dir, const OptionWords& w = {});
CLI::Option* addPresetDirOption(CLI::App& cmd, std::string& dir, const OptionWords& w = {});
CLI::Option* addEngineModulesOption(CLI::App& cmd, std::string& dir, const OptionWords& w = {});
// --budget-ms, --budget-ratio and --max-error: a time or error budget (what it chooses: `w`).
CLI::Option* addBudgetMsOption(CLI::App& cmd, double& ms, const OptionWords& w);
CLI::Option* addBudgetRatioOption(CLI::App& cmd, double& ratio, const OptionWords& w);
CLI::Option* addMaxErrorOption(CLI::App& cmd, double& maxError, const OptionWords& w = {});
// --objective still|motion (what it ranks: `w`).
CLI::Option* addObjectiveOption(CLI::App& cmd, std::string& objective, const OptionWords& w);
// --quiet and --no-plot.
CLI::Option* addQuietFlag(CLI::App& cmd, bool& quiet, const OptionWords& w = {});
CLI::Option* addNoPlotFlag(CLI::App& cmd, bool& plot);

} // namespace ssao
