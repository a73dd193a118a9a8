#include "results/bench_finish.h"

#include "cli/scene_options.h"
#include "metrics/motion_metrics.h"
#include "results/bench_report.h"
#include "settings/preset.h"
#include "util/error.h"

#include <cstdio>
#include <filesystem>
#include <optional>

namespace ssao {
namespace {

void printBenchSummary(const BenchRun& run, const std::string& out, bool plot) {
    const Sweep& sweep = run.sweep;
    const ConfigSummary& b = run.summary[sweep.baseline];
    std::printf("baseline %s: %.3f ms, RMSE %.4f, PSNR %.2f dB (geometry) %.2f dB (full frame)\n",
                sweep.configs[sweep.baseline].label.c_str(), b.gpuMs, b.rmse, b.psnrGeometrySrgb, b.psnrFullSrgb);
    const Objective o = runObjective(run);
    const size_t cheap = fastestAtMostBaselineError(run), best = mostAccurate(run);
    if (cheap != std::string::npos)
        std::printf("fastest at most the baseline's error %s: %s: %.3f ms (%.3fx), %s %.4f (%.3fx)\n", objectiveWhere(o),
                    sweep.configs[cheap].label.c_str(), run.summary[cheap].gpuMs, run.summary[cheap].timeRatio,
                    objectiveErrorName(o), objectiveError(run.summary[cheap], o), objectiveRatio(run.summary[cheap], o));
    if (best != std::string::npos)
        std::printf("lowest error%s: %s: RMSE %.4f (%.3fx) in %.3f ms%s (%.3fx)\n",
                    run.facts.contains("motion") ? " on a still camera" : "", sweep.configs[best].label.c_str(),
                    run.summary[best].rmse, run.summary[best].rmseRatio, run.summary[best].gpuMs,
                    run.summary[best].unsureTimeViews ? " (unsure: its frames' times varied past 2x)" : "",
                    run.summary[best].timeRatio);
    if (const size_t m = mostAccurateInMotion(run); m != std::string::npos) {
        const ConfigSummary& s = run.summary[m];
        std::printf("lowest error in motion: %s: motion score %.4f (%.3fx) in %.3f ms (%.3fx)\n",
                    sweep.configs[m].label.c_str(), s.motionScore, s.motionRatio, s.gpuMs, s.timeRatio);
        if (const std::string d = winnersDifferLine(run, [](const std::string& x) { return x; }); !d.empty())
            std::printf("%s\n", d.c_str());
    }
    int front = 0;
    for (const auto& s : run.summary)
        front += s.pareto;
    std::printf("%d configurations on the Pareto front of time against %s; wrote %s/{results.csv,summary.csv,"
                "results.json,report.md,report.html%s}\n",
                front, objectiveTitle(o), out.c_str(), plot ? ",pareto.png,pareto.svg" : "");
}

// The preset context of the answer: the first viewpoint of the first scene, as the run recorded it.
std::optional<AnswerContext> answerContext(const BenchRun& run, const std::string& out, float& radius) {
    const nlohmann::json& f = run.facts;
    if (!f.contains("scene_specs") || f["scene_specs"].empty() || !f.contains("scenes") || f["scenes"].empty())
        return std::nullopt;
    const nlohmann::json& sc = f["scenes"][0];
    if (!sc.contains("viewpoints") || sc["viewpoints"].empty()) return std::nullopt;
    AnswerContext ctx;
    ctx.scene = f["scene_specs"][0].get<std::string>();
    parseSizeOption(f.value("size", ""), ctx.width, ctx.height);
    ctx.camera = cameraFromJson(sc["viewpoints"][0]["camera"], "results.json camera");
    ctx.referenceRays = f["reference"].value("rays", 0);
    ctx.presetPath = (std::filesystem::path(out) / "answer.json").string();
    radius = sc.value("radius", 0.0f);
    return ctx;
}

} // namespace

int finishBench(BenchRun& run, const std::string& out, const std::string& title, bool plot, bool quiet,
                const Question& q) {
    if (q.objective == Objective::Motion && !run.facts.contains("motion"))
        throw Error("--objective motion ranks by the motion score, and these rows were not scored in motion "
                    "(bench --motion)");
    run.facts["objective"] = objectiveKey(q.objective);
    run.summary = summarize(run.views, run.sweep.configs.size(), run.sweep.baseline, q.objective);
    std::optional<Answer> answer; // opens the reports, so it comes first
    if (q.asked()) {
        float radius = 0;
        const auto ctx = answerContext(run, out, radius);
        if (!ctx) throw Error("the results hold no viewpoint of the first scene to answer on");
        answer = answerQuestion(run, q, *ctx, radius);
    }
    writeBenchFiles(run, out, answer ? &*answer : nullptr);
    if (plot) plotBench(out, title, quiet, q.objective);
    if (!quiet) printBenchSummary(run, out, plot);
    if (answer) std::printf("%s\n", answer->line.c_str());
    long bad = 0;
    for (const auto& s : run.summary)
        bad += s.nonFinite;
    if (bad > 0) throw Error(std::to_string(bad) + " non-finite AO pixels in the benchmark (see results.csv)");
    return 0;
}

} // namespace ssao
