// The report's "What the screen cannot see": every error split into the technique's (against the
// screen-space oracle: what settings can still fix) and the screen's (the oracle against the
// truth: what the G-buffer does not hold), per scene, for the techniques at their defaults and the
// shipped presets of the sweep. Markdown, from the run's rows; empty when no oracle was traced.
#pragma once
#include "results/bench_results.h"

#include <string>

namespace ssao {

std::string splitMarkdown(const BenchRun& run);

} // namespace ssao
