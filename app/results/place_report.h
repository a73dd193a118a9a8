// The report's "Where the error lives": each configuration's squared error against the truth split
// by where its pixels are (metrics/error_places.h: the frame's border, silhouettes, concave creases
// by opening angle, convex edges, the open; and R in pixels), summed over each scene's views, for the
// baseline, the front and the lowest-error row. Markdown, from the run's rows; empty when no row
// kept it.
#pragma once
#include "results/bench_results.h"

#include <string>

namespace ssao {

std::string placeMarkdown(const BenchRun& run);

} // namespace ssao
