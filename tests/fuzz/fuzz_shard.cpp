// libFuzzer target: a bench shard's results.json, the file `bench merge` reads from folders other
// machines wrote. Checked by the same reader merge uses; a run it accepts is summarised and
// written as results.json and report.md in memory, as merge does. Any ssao::Error is a correct
// answer; a crash, a sanitizer report, a hang or another exception type is not.
#include "results/bench_report.h"
#include "results/results_check.h"
#include "util/error.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        ssao::BenchRun run = ssao::parseResultsText(text, "fuzz/results.json");
        run.summary = ssao::summarize(run.views, run.sweep.configs.size(), run.sweep.baseline);
        ssao::resultsJson(run);
        ssao::benchMarkdown(run, "pareto.png");
    } catch (const ssao::Error&) {
    }
    return 0;
}
