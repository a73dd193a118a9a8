// Writes a benchmark's results: results.csv (per view), summary.csv (per configuration),
// results.json (both, with the run's facts), report.md (the Pareto front and every row against
// the baseline), report.html (results/report_html.h) and the plot through plot_pareto.py.
#pragma once
#include "results/bench_answer.h"
#include "results/bench_results.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ssao {

// `answer`: the answer to the user's question (bench --budget-ms ...), which opens both reports.
void writeBenchFiles(const BenchRun& run, const std::string& dir, const Answer* answer = nullptr);

// Markdown: the answer (if asked), the run's facts, the front, the headline sentences and the full table.
std::string benchMarkdown(const BenchRun& run, const std::string& plotFile, const Answer* answer = nullptr);
// Runs plot_pareto.py with the objective's error on its y axis; returns false (after printing one
// line) when Python/matplotlib is missing.
bool plotBench(const std::string& dir, const std::string& title, bool quiet, Objective objective = Objective::Still);

// The rows quoted in the closing line: the fastest configuration whose error (the run's objective,
// runObjective) is at most the baseline's, and the lowest still RMSE. npos when none.
size_t fastestAtMostBaselineError(const BenchRun& run);
size_t mostAccurate(const BenchRun& run);
// With bench --motion: the lowest motion score (npos without motion columns).
size_t mostAccurateInMotion(const BenchRun& run);
// One sentence when the still camera's most accurate row is not the most accurate in motion ("" when
// they agree or there is no motion column): a still answer is not the one a moving camera needs.
// `name` writes a configuration's label for the sink (markdownCell for report.md).
std::string winnersDifferLine(const BenchRun& run, const std::function<std::string(const std::string&)>& name);

} // namespace ssao
