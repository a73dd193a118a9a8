#include "results/bench_answer.h"

#include "measure/bench_run.h"
#include "metrics/motion_metrics.h"
#include "output/escape.h"
#include "settings/params.h"
#include "settings/preset.h"
#include "util/number_text.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ssao {

size_t answer(const BenchRun& run, const Question& q) {
    size_t best = std::string::npos;
    auto err = [&](const ConfigSummary& s) { return objectiveError(s, q.objective); };
    for (const ConfigSummary& s : run.summary) {
        if (!std::isfinite(err(s)) || !std::isfinite(s.timeRatio)) continue;
        if (run.sweep.configs[s.config].isEngine()) continue; // the answer is a preset ssaolab renders
        if (q.budgetMs > 0 && !(s.gpuMs <= q.budgetMs)) continue;
        if (q.budgetRatio > 0 && !(s.timeRatio <= q.budgetRatio)) continue;
        if (q.maxError > 0 && !(err(s) <= q.maxError)) continue;
        if (best == std::string::npos) {
            best = s.config;
            continue;
        }
        const ConfigSummary& b = run.summary[best];
        // A budget asks for accuracy; an error bound alone asks for speed.
        const bool budget = q.budgetMs > 0 || q.budgetRatio > 0;
        const bool better = budget ? err(s) < err(b) || (err(s) == err(b) && s.timeRatio < b.timeRatio)
                                   : s.timeRatio < b.timeRatio || (s.timeRatio == b.timeRatio && err(s) < err(b));
        if (better) best = s.config;
    }
    return best;
}

std::vector<std::string> assignments(const Settings& s) {
    std::vector<std::string> out;
    for (const Param& p : paramTable()) {
        if (!p.applies(s) || p.isDefault(s)) continue;
        const double v = p.get(s);
        std::string text = p.format(v);
        if (p.type == Param::Type::Float) {
            char b[32];
            std::snprintf(b, sizeof b, "%.9g", double(float(v)));
            text = b;
        }
        out.push_back(p.key + "=" + text);
    }
    return out;
}

namespace {
std::string num(double v, int digits) {
    return numberText(v, "%.*g", digits);
}

std::string questionText(const Question& q) {
    std::string t;
    auto add = [&](const std::string& part) { t += (t.empty() ? "" : " and ") + part; };
    if (q.budgetMs > 0) add("within " + num(q.budgetMs, 4) + " ms");
    if (q.budgetRatio > 0) add("within " + num(q.budgetRatio, 4) + "x the baseline's time");
    if (q.maxError > 0) add("at most " + std::string(objectiveErrorName(q.objective)) + " " + num(q.maxError, 4));
    return t + ", " + objectiveWhere(q.objective);
}

// "RMSE 0.0819 (0.573x)" or "motion score 0.0912 (0.61x)".
std::string errorText(const ConfigSummary& s, Objective o) {
    return std::string(objectiveErrorName(o)) + " " + num(objectiveError(s, o), 4) + " (" + num(objectiveRatio(s, o), 3) + "x)";
}

// Temporal accumulation blends frames of an unmoving view: the row's still error is the blend's (in
// motion its history follows the camera path, and the motion score holds that).
std::string stillCameraNote(const BenchRun& run, size_t c, Objective o) {
    const Settings& s = run.sweep.configs[c].settings;
    if (!s.temporal.enabled || o == Objective::Motion) return "";
    const double first = run.summary[c].rmseFirstFrame, base = run.summary[run.sweep.baseline].rmse;
    return "holds for a still camera: temporal accumulation blends " + std::to_string(s.temporal.frames) +
           " frames of an unmoving view; its first frame alone (a cut, a new view) has RMSE " + num(first, 4) + " (" +
           num(first / base, 3) + "x the baseline's)";
}

// The answer's preset: the settings at the bench's R, the scene, size and first camera it was judged on.
void writeAnswerPreset(const BenchRun& run, const Answer& a, const AnswerContext& ctx, float radius) {
    const ConfigSummary& s = run.summary[a.config];
    const BenchConfig& cfg = run.sweep.configs[a.config];
    Preset p;
    p.name = std::filesystem::path(ctx.presetPath).stem().string();
    p.description = "ssaolab bench answer (" + a.question + "): " + cfg.label + ", " + num(s.gpuMs, 4) + " ms (" +
                    num(s.timeRatio, 3) + "x " + run.sweep.configs[run.sweep.baseline].label + "), " + errorText(s, a.objective) +
                    (a.stillCamera.empty() ? "" : "; " + a.stillCamera);
    p.settings = withRadius(cfg.settings, radius);
    std::error_code ec;
    const bool file = ctx.scene.rfind("builtin:", 0) != 0;
    p.scene = file ? std::filesystem::absolute(ctx.scene, ec).string() : ctx.scene;
    p.size = std::make_pair(ctx.width, ctx.height);
    p.camera = ctx.camera;
    p.scores = {{"question", a.question}, {"label", cfg.label},     {"gpu_ms", s.gpuMs},
                {"time_ratio", s.timeRatio}, {"rmse", s.rmse},      {"rmse_ratio", s.rmseRatio},
                {"objective", objectiveKey(a.objective)}, {"still_camera_only", !a.stillCamera.empty()}};
    if (a.objective == Objective::Motion)
        p.scores["motion_score"] = s.motionScore, p.scores["motion_score_ratio"] = s.motionRatio;
    writePresetFile(p, ctx.presetPath);
}
} // namespace

Answer answerQuestion(const BenchRun& run, const Question& q, const AnswerContext& ctx, float radius) {
    Answer a;
    a.question = questionText(q);
    a.objective = q.objective;
    a.config = answer(run, q);
    if (a.config == std::string::npos) {
        // Say what comes closest, so the user knows how far off the question is.
        auto err = [&](size_t c) { return objectiveError(run.summary[c], q.objective); };
        for (const auto& s : run.summary) {
            if (s.gpuMs < run.summary[a.fastest].gpuMs) a.fastest = s.config;
            if (err(s.config) < err(a.mostAccurate) || !std::isfinite(err(a.mostAccurate))) a.mostAccurate = s.config;
        }
        a.line = "answer: no configuration is " + a.question + " (fastest: " + run.sweep.configs[a.fastest].label + ", " +
                 num(run.summary[a.fastest].gpuMs, 4) + " ms; most accurate: " +
                 run.sweep.configs[a.mostAccurate].label + ", " + objectiveErrorName(q.objective) + " " +
                 num(err(a.mostAccurate), 4) + ")";
        return a;
    }
    const size_t c = a.config;
    const ConfigSummary& s = run.summary[c];
    a.stillCamera = stillCameraNote(run, c, q.objective);
    a.command = "ssaolab render --preset " + ctx.presetPath + " --reference --reference-rays " +
                std::to_string(ctx.referenceRays);
    writeAnswerPreset(run, a, ctx, radius);
    std::string set;
    for (const auto& as : assignments(withRadius(run.sweep.configs[c].settings, radius)))
        set += " --set " + as;
    // The preset renders one view, the first; say its own numbers when the summary is over more.
    std::string first;
    for (const ViewResult& v : run.views)
        if (v.config == c && v.scene == run.views.front().scene && s.views > 1) {
            const double e = q.objective == Objective::Motion ? motionScore(v.motion.rmseMean, v.motion.instability)
                                                              : v.error.rmse;
            first = " (its view '" + v.viewpoint + "' alone: " + objectiveErrorName(q.objective) + " " + num(e, 4) + ")";
            break;
        }
    a.line = "answer (" + a.question + "): " + run.sweep.configs[c].label + ": " + num(s.gpuMs, 4) + " ms (" +
             num(s.timeRatio, 3) + "x the baseline's), " + errorText(s, q.objective) +
             (a.stillCamera.empty() ? "" : "; " + a.stillCamera) + "; flags:" + set + "; preset " + ctx.presetPath +
             first + " (" + a.command + ")";
    return a;
}

namespace {
// "0.469x the baseline's time (1.03 ms), 0.573x its error (RMSE 0.0819)": the ratios first, as the plot reads.
std::string ratios(const ConfigSummary& s, Objective o) {
    return num(s.timeRatio, 3) + "x the baseline's time (" + num(s.gpuMs, 4) + " ms), " + num(objectiveRatio(s, o), 3) +
           "x its error (" + objectiveErrorName(o) + " " + num(objectiveError(s, o), 4) + ")";
}
} // namespace

std::string answerMarkdown(const BenchRun& run, const Answer& a) {
    const auto& cfgs = run.sweep.configs;
    std::string md = "### Your question: " + markdownCell(a.question) + "\n\n";
    if (a.config == std::string::npos)
        return md + "No configuration is " + markdownCell(a.question) + ". Fastest: **" +
               markdownCell(cfgs[a.fastest].label) + "**, " + ratios(run.summary[a.fastest], a.objective) + "; most accurate: **" +
               markdownCell(cfgs[a.mostAccurate].label) + "**, " + ratios(run.summary[a.mostAccurate], a.objective) + ".\n\n";
    md += "**" + markdownCell(cfgs[a.config].label) + "**: " + ratios(run.summary[a.config], a.objective) + ".";
    if (!a.stillCamera.empty()) md += " Its error " + markdownCell(a.stillCamera) + ".";
    return md + "\n\nRender it: " + markdownCell(a.command) + "\n\n";
}

std::string answerHtml(const BenchRun& run, const Answer& a) {
    const auto& cfgs = run.sweep.configs;
    std::string h = "<section id=\"answer\"><h2>Your question: " + htmlText(a.question) + "</h2><p>";
    if (a.config == std::string::npos)
        return h + "No configuration is " + htmlText(a.question) + ". Fastest: <b>" + htmlText(cfgs[a.fastest].label) +
               "</b>, " + ratios(run.summary[a.fastest], a.objective) + "; most accurate: <b>" +
               htmlText(cfgs[a.mostAccurate].label) + "</b>, " + ratios(run.summary[a.mostAccurate], a.objective) + ".</p></section>";
    h += "<b>" + htmlText(cfgs[a.config].label) + "</b>: " + ratios(run.summary[a.config], a.objective) + ".";
    if (!a.stillCamera.empty()) h += " Its error " + htmlText(a.stillCamera) + ".";
    return h + "</p><p>Render it: <code>" + htmlText(a.command) + "</code></p></section>";
}

} // namespace ssao
