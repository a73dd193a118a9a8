// The benchmark's answer to a user's question, in a user's words: "the most accurate setting
// within X ms" (--budget-ms) or "within X times the baseline's time" (--budget-ratio, the plot's
// own axis) or "the cheapest setting at most E wrong" (--max-error). One line with the
// configuration, its time and error and their ratios to the baseline, a ready `--set` line, and a
// preset file that reproduces it (scene, size, camera and R included: `render --preset` renders
// the same numbers); the same answer opens report.md and report.html. Every answer names its
// objective (bench --objective): the still frame's RMSE, or the motion score along each view's
// camera path; a still answer that accumulates frames (temporal) says its error holds for a still camera.
#pragma once
#include "results/bench_results.h"
#include "scene/camera.h"

#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct Question {
    double budgetMs = 0;    // > 0: the lowest error whose time (ms, mean over views) is at most this
    double maxError = 0;    // > 0: the lowest time ratio whose error is at most this
    double budgetRatio = 0; // > 0: the lowest error whose time ratio (x the baseline's) is at most this
    Objective objective = Objective::Still; // which error: the still RMSE or the motion score
    bool asked() const { return budgetMs > 0 || maxError > 0 || budgetRatio > 0; }
};

// The configuration that answers, npos when none does. A budget and an error bound: within both,
// the most accurate.
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

// The answer as every output gives it.
struct Answer {
    std::string question;               // "within 0.5x the baseline's time, in motion"
    Objective objective = Objective::Still; // what its error is
    size_t config = std::string::npos;  // npos: no configuration meets the question
    std::string line;                   // stdout's one line
    std::string command;                // renders the answer's preset against the reference
    std::string stillCamera;            // "" or why its error holds for a still camera only
    size_t fastest = 0, mostAccurate = 0; // what comes closest when none answers
};

// Answers `q`, writing the preset (ctx.presetPath) when a configuration does.
Answer answerQuestion(const BenchRun& run, const Question& q, const AnswerContext& ctx, float radius);
// The section that opens report.md / report.html (every input string escaped for its file).
std::string answerMarkdown(const BenchRun& run, const Answer& a);
std::string answerHtml(const BenchRun& run, const Answer& a);

} // namespace ssao
