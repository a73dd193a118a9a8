// `tune --engine`'s own options (commands/tune/engine_tune.h): part of TuneOptions, so one `tune` command
// line takes both.
#pragma once
#include <string>

namespace ssao {

struct EngineTuneOptions {
    std::string engine;  // --engine NAME: tune this web engine's own settings (engines/engine_table.h)
    std::string modules; // --engine-modules DIR: the npm packages (default: the build folder's peers/node_modules)
    std::string snippet; // --snippet FILE: the JavaScript (default: --out with .js)
    int timingFrames = 10; // frames whose median times defaults and tuned at the end
    // The time budget that chooses the cost parameters (0 = none: the engine's defaults): AO ms, or a
    // multiple of the defaults' AO time measured in the same run.
    double budgetMs = 0, budgetRatio = 0;
};

} // namespace ssao
