// `ssaolab tune`: fits one technique's artistic parameters to the ray-traced reference, as XeGTAO
// tuned its defaults: minimise the geometry-pixel MSE over training viewpoints by coordinate
// search (each parameter on a grid inside a bracket that halves every round), then report the
// score on held-out viewpoints and on held-out scenes, and save the tuned preset as JSON.
// Parameters searched: every float parameter of the technique's own group that applies
// (kernel.bias ...). A radius multiplier (the technique's radius = m x the reference's R) and
// ao.power only when named by --knob: they fit the numbers without the physics.
#pragma once
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
    int views = 6;  // even-numbered viewpoints train, odd ones are held out
    int rounds = 3; // bracket halvings
    int grid = 7;   // values per parameter per round
    int referenceRays = 256;
    float radiusScene = 0.05f;
    // Only these knobs (keys, "radius_multiplier" or "ao.power"); empty = the technique's float rows:
    // R stays the reference's and power 1 (a power that only darkens is not physics).
    std::vector<std::string> knobs;
    std::vector<std::string> sets; // KEY=VALUE applied to the start (a quality level's sample counts)
    std::string out = "tuned.json";
    std::string presetDir;
    bool quiet = false;
};

void addTuneOptions(CLI::App& cmd, TuneOptions& o);
int runTune(const TuneOptions& o);

} // namespace ssao
