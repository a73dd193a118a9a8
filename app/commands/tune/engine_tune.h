// `ssaolab tune --engine NAME`: a web engine's own AO settings fitted to the ray-traced reference.
// The engine runs for real (engines/engine_runner.h) on each view of the --scene glTF files, at the
// view's camera, size and R; its AO is scored in-process against the same reference `tune` uses.
// Coordinate search over the engine's shape parameters only (each over a grid inside a bracket
// that halves every round, as `tune` searches); cost parameters keep the engine's defaults (a
// budget chooses them, never the error). Start and "defaults": the engine's defaults with every
// length set from R, as `make peers` runs it. Even viewpoints train, odd ones and every view of a
// --held-out-scene are held out; a fit that raises the held-out error is refused unless
// --save-overfit (commands/tune/tune_guard.h). Writes the settings as JSON (--out) and a snippet for the
// engine's API (--snippet).
#pragma once
#include "commands/tune/tune_command.h"

namespace CLI {
class App;
}

namespace ssao {

void addEngineTuneOptions(CLI::App& cmd, EngineTuneOptions& o);
int runEngineTune(const TuneOptions& o);

} // namespace ssao
