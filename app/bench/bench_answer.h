// The benchmark's answer to a user's question, in a user's words: "the most accurate setting
// within X ms" (--budget-ms) or "the cheapest setting at most E wrong" (--max-error). One line
// with the configuration, its time and error and their ratios to the baseline, a ready `--set`
// line, and a preset file that reproduces it (scene, size, camera and R included: `render
// --preset` renders the same numbers).
#pragma once
#include "bench/bench_results.h"
#include "scene/camera.h"

#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct Question {
    double budgetMs = 0; // > 0: the lowest RMSE whose time (ms, mean over views) is at most this
    double maxError = 0; // > 0: the lowest time ratio whose RMSE is at most this
    bool asked() const { return budgetMs > 0 || maxError > 0; }
};

// The configuration that answers, npos when none does. Both set: within the budget and at most
// the error, the most accurate.
size_t answer(const BenchRun& run, const Question& q);

// "key=value" for every row that applies and differs from the defaults (floats to 9 digits, so
// the radius survives the round trip).
std::vector<std::string> assignments(const Settings& s);

// Where the preset for the answer is written and how to render it.
struct AnswerContext {
    std::string scene; // spec as given (a relative path is made absolute)
    int width = 0, height = 0;
    Camera camera; // the first viewpoint of the first scene
    int referenceRays = 0;
    std::string presetPath; // OUT/answer.json
};

// Writes the preset and returns the one line (or the line saying that nothing meets the question).
std::string answerLine(const BenchRun& run, const Question& q, const AnswerContext& ctx, float radius);

} // namespace ssao
