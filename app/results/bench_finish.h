// The end of `bench` and of `bench merge`: summaries, files, plot, the printed summary and the
// answer to --budget-ms / --budget-ratio / --max-error (results/bench_answer.h), which also opens
// report.md and report.html. `q.objective` decides the front and every answer; the run records it
// (results.json's facts.objective).
#pragma once
#include "results/bench_answer.h"
#include "results/bench_results.h"

#include <string>

namespace ssao {

// Returns the exit code; throws ssao::Error when the run holds non-finite AO, or when the objective is
// motion and the rows were not scored in motion.
int finishBench(BenchRun& run, const std::string& out, const std::string& title, bool plot, bool quiet,
                const Question& q);

} // namespace ssao
