#include "bench/bench_answer.h"

#include "bench/bench_run.h"
#include "settings/params.h"
#include "settings/preset.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ssao {

size_t answer(const BenchRun& run, const Question& q) {
    size_t best = std::string::npos;
    for (const ConfigSummary& s : run.summary) {
        if (!std::isfinite(s.rmse) || !std::isfinite(s.timeRatio)) continue;
        if (q.budgetMs > 0 && !(s.gpuMs <= q.budgetMs)) continue;
        if (q.maxError > 0 && !(s.rmse <= q.maxError)) continue;
        if (best == std::string::npos) {
            best = s.config;
            continue;
        }
        const ConfigSummary& b = run.summary[best];
        // A budget asks for accuracy; an error bound alone asks for speed.
        const bool better = q.budgetMs > 0 ? s.rmse < b.rmse || (s.rmse == b.rmse && s.timeRatio < b.timeRatio)
                                           : s.timeRatio < b.timeRatio || (s.timeRatio == b.timeRatio && s.rmse < b.rmse);
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
    char b[32];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    return b;
}
std::string questionText(const Question& q) {
    std::string t;
    if (q.budgetMs > 0) t += "within " + num(q.budgetMs, 4) + " ms";
    if (q.maxError > 0) t += std::string(t.empty() ? "" : " and ") + "at most RMSE " + num(q.maxError, 4);
    return t;
}
} // namespace

std::string answerLine(const BenchRun& run, const Question& q, const AnswerContext& ctx, float radius) {
    const size_t c = answer(run, q);
    if (c == std::string::npos) {
        // Say what comes closest, so the user knows how far off the question is.
        size_t fastest = 0, best = 0;
        for (const auto& s : run.summary) {
            if (s.gpuMs < run.summary[fastest].gpuMs) fastest = s.config;
            if (s.rmse < run.summary[best].rmse) best = s.config;
        }
        return "answer: no configuration is " + questionText(q) + " (fastest: " + run.sweep.configs[fastest].label + ", " +
               num(run.summary[fastest].gpuMs, 4) + " ms; most accurate: " + run.sweep.configs[best].label + ", RMSE " +
               num(run.summary[best].rmse, 4) + ")";
    }
    const ConfigSummary& s = run.summary[c];
    const BenchConfig& cfg = run.sweep.configs[c];
    Preset p;
    p.name = std::filesystem::path(ctx.presetPath).stem().string();
    p.description = "ssaolab bench answer (" + questionText(q) + "): " + cfg.label + ", " + num(s.gpuMs, 4) + " ms (" +
                    num(s.timeRatio, 3) + "x " + run.sweep.configs[run.sweep.baseline].label + "), RMSE " +
                    num(s.rmse, 4) + " (" + num(s.rmseRatio, 3) + "x)";
    p.settings = withRadius(cfg.settings, radius);
    std::error_code ec;
    const bool file = ctx.scene.rfind("builtin:", 0) != 0;
    p.scene = file ? std::filesystem::absolute(ctx.scene, ec).string() : ctx.scene;
    p.size = std::make_pair(ctx.width, ctx.height);
    p.camera = ctx.camera;
    writePresetFile(p, ctx.presetPath);
    std::string set;
    for (const auto& a : assignments(p.settings))
        set += " --set " + a;
    // The preset renders one view, the first; say its own numbers when the summary is over more.
    std::string first;
    for (const ViewResult& v : run.views)
        if (v.config == c && v.scene == run.views.front().scene && s.views > 1) {
            first = " (its view '" + v.viewpoint + "' alone: RMSE " + num(v.error.rmse, 4) + ")";
            break;
        }
    return "answer (" + questionText(q) + "): " + cfg.label + ": " + num(s.gpuMs, 4) + " ms (" + num(s.timeRatio, 3) +
           "x the baseline's), RMSE " + num(s.rmse, 4) + " (" + num(s.rmseRatio, 3) + "x); flags:" + set +
           "; preset " + ctx.presetPath + first + " (ssaolab render --preset " + ctx.presetPath +
           " --reference --reference-rays " + std::to_string(ctx.referenceRays) + ")";
}

} // namespace ssao
