// `ssaolab tune`: fits one technique's artistic parameters to the ray-traced reference, as XeGTAO
// tuned its defaults: minimise the geometry-pixel MSE over training viewpoints by coordinate
// search (each parameter on a grid inside a bracket that halves every round), then report the
// score on held-out viewpoints and on held-out scenes, and save the tuned preset as JSON.
// Parameters searched: every float parameter of the technique's own group that applies
// (kernel.bias ...) but a radius multiplier. A radius multiplier (tune's: the technique's radius =
// m x the reference's R; a technique's own, gtao.radius_multiplier: its search past R) and ao.power
// only when named by --knob: they fit the numbers without the physics.
// --objective motion minimises, per view, the motion score squared (mean per-frame RMSE^2 plus
// instability^2) along a camera path (measure/motion_measure.h) instead of the still frame's MSE. A fit that raises the
// held-out error is not saved unless --save-overfit (commands/tune/tune_guard.h).
#pragma once
#include "engines/engine_options.h"
#include "scene/camera_path.h"
#include "settings/params.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ssao {

struct TuneOptions {
    std::string technique = defaultSettings().ao.technique; // the default settings' technique
    std::string preset;              // starting point (default: the technique's defaults)
    std::vector<std::string> scenes;        // training scenes; default builtin:showcase
    std::vector<std::string> heldOutScenes; // judged only, every viewpoint: never fitted on
    std::string size = "640x360";
    int views = 8;  // even-numbered viewpoints train, odd ones are held out
    int rounds = 3; // bracket halvings
    int grid = 7;   // values per parameter per round
    int referenceRays = 256;
    float radiusScene = 0.05f;
    // Only these knobs (keys, "radius_multiplier" or "ao.power"); empty = the technique's float rows
    // but its radius multiplier: R stays the reference's and power 1 (a power that only darkens is not physics).
    std::vector<std::string> knobs;
    std::vector<std::string> sets; // KEY=VALUE applied to the start (a quality level's sample counts)
    std::string out = "tuned.json";
    std::string presetDir;
    std::string shaderDir; // default: the installation's (or source tree's) shaders/
    bool saveOverfit = false; // save even when the held-out error rose (with a warning)
    // still: the mean geometry MSE of each view's still frame; motion: along each view's camera path
    // (measure/motion_measure.h), mean over its frames of the per-frame MSE + instability^2.
    std::string objective = "still";
    std::string camera; // --camera: the training scenes' first viewpoint, file coordinates ("" = their own)
    CameraPathSpec motionPath;
    EngineTuneOptions engine; // --engine: a web engine's own settings instead (commands/tune/engine_tune.h)
    bool quiet = false;
};

void addTuneOptions(CLI::App& cmd, TuneOptions& o);
int runTune(const TuneOptions& o);

} // namespace ssao
