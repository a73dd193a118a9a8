// report.html: a benchmark people look at, not only read. One self-contained, offline file (no
// network, no CDN, no script from elsewhere): the time-against-error plot overall and per scene
// as inline SVG (every point named on hover, the front and the baseline labelled, the reference's
// noise floor as a band), the thumbnails of every front configuration and the baseline (AO,
// signed error heat map, reference; PNG as data: URIs), and a table that sorts by any column.
// A script checks on load that every image decoded and the plots hold points, and records any
// error in <body data-check=...> (tests/cli/test_report_html.cpp reads it in a real browser).
#pragma once
#include "results/bench_answer.h"
#include "results/bench_results.h"

#include <string>

namespace ssao {

// `dir`: the run's output folder, whose thumbs/ the page embeds (measure/thumbnails.h); `answer`: the
// answer to the user's question, which opens the page.
std::string benchHtml(const BenchRun& run, const std::string& dir, const Answer* answer = nullptr);

// RFC 4648 base64 of `bytes`.
std::string base64(const std::string& bytes);

} // namespace ssao
