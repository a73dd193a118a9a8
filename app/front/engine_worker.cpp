#include "front/engine_worker.h"

#include "../../shaders/include/view_colors.h"
#include "engines/engine_snippet.h"
#include "metrics/evaluate.h"
#include "util/error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace ssao {

namespace {

// The settings a sample ran with as JavaScript: every shape row, and the cost rows the harness
// moved off the engine's default; comments say where they come from and what they scored.
std::string viewSnippet(const EngineWorker::Job& job, const EngineTable& t, const EngineSample& s) {
    std::vector<std::pair<std::string, double>> values;
    for (const EngineParam& p : t.params) {
        const auto it = s.values.find(p.name);
        if (it == s.values.end()) continue;
        if (p.role == EngineParam::Role::Shape || (p.role == EngineParam::Role::Cost && it->second != p.defaultValue))
            values.emplace_back(p.name, exportedValue(it->second));
    }
    const std::string what =
        s.candidate.tuned()     ? "the fit named below (ssaolab tune --engine) on this view"
        : s.candidate.shipped ? "the engine as its package ships it (its defaults verbatim)"
                              : "the engine's defaults with every length from R, as ssaolab's make peers sets them";
    char b[320];
    std::snprintf(b, sizeof b, "the view below at %dx%d, R = %.4g scene units: geometry RMSE %.4f against the ray-traced reference (%d rays)",
                  job.width, job.height, double(job.radius), s.error.rmse, job.reference ? job.reference->samples : 0);
    SnippetFacts facts{{"ssaolab view: " + t.title + " (" + t.package + " " + t.version + ")", what, b}, {{"scene", job.sceneName}}};
    if (s.candidate.tuned()) facts.names.emplace_back("fit", std::filesystem::path(s.candidate.file).filename().string());
    return engineSnippet(t, values, facts);
}

// The AO painted as the explorer's views paint a buffer of its own (shaders/display/view.frag):
// where the reference's primary ray missed, the sky's grey.
Image shownAo(const Image& ao, const ReferenceImage& ref) {
    Image out = ao;
    if (ref.width != ao.width || ref.height != ao.height || ref.geometry.size() != ao.data.size()) return out;
    for (size_t i = 0; i < out.data.size(); ++i)
        if (!(ref.geometry[i] > 0.0f)) out.data[i] = float(SSAO_SKY_GREY);
    return out;
}

} // namespace

std::string engineToolsReason(const std::string& message) {
    const std::string cut = "in Chromium: ";
    const size_t at = message.find(cut);
    return oneLine(at == std::string::npos ? message : message.substr(at + cut.size()));
}

// Normal priority, unlike the reference's tracers: the browser's frames are timed, and under the
// idle policy any other process would stretch them. It starts once ssaolab's candidates are done.
EngineWorker::EngineWorker(std::function<void()> wake)
    : jobs_([this](const Job& job) { measure(job); }, std::move(wake)) {}

void EngineWorker::start(Job job) {
    State fresh;
    fresh.total = job.candidates.size();
    jobs_.start(std::move(job), std::move(fresh)); // the running job, if any, stops after its session
}

void EngineWorker::measure(const Job& job) {
    std::vector<std::string> order; // the engines, in the order their candidates come
    for (const EngineCandidate& c : job.candidates)
        if (std::find(order.begin(), order.end(), c.engine) == order.end()) order.push_back(c.engine);
    std::vector<std::pair<EngineTable, EngineTools>> engines;
    try {
        for (const std::string& name : order) {
            EngineTable t = findEngine(name);
            EngineTools tools = locateEngineTools(job.modules, t);
            engines.emplace_back(std::move(t), std::move(tools));
        }
    } catch (const std::exception& e) {
        const std::string why = engineToolsReason(e.what());
        publish(job, [&](State& s) { s.toolsError = why, s.done = true; });
        return;
    }
    for (const auto& [t, tools] : engines) {
        std::vector<const EngineCandidate*> cands;
        for (const EngineCandidate& c : job.candidates)
            if (c.engine == t.engine) cands.push_back(&c);
        const std::string title = engineShortTitle(t);
        if (!publish(job, [&](State& s) { s.running = title; })) return;
        try {
            measureEngine(job, cands, t, tools);
        } catch (const std::exception& e) {
            const std::string why = title + ": " + oneLine(e.what());
            if (!publish(job, [&](State& s) { s.errors.push_back(why); })) return;
        }
    }
    publish(job, [](State& s) { s.running.clear(), s.done = true; });
}

void EngineWorker::measureEngine(const Job& job, const std::vector<const EngineCandidate*>& cands,
                                 const EngineTable& t, const EngineTools& tools) {
    EngineRunner runner(tools, t, job.sceneFile, job.width, job.height, {{job.camera, job.radius}});
    auto add = [&](const EngineCandidate& c, const EngineResult& r) {
        auto s = std::make_shared<EngineSample>();
        s->candidate = c;
        s->title = t.title;
        s->ao = r.ao;
        s->shown = shownAo(r.ao, *job.reference);
        s->error = evaluate(r.ao, *job.reference).metrics; // as tune --engine scores it
        if (s->error.nonFinite > 0) throw Error(t.title + " returned non-finite AO");
        s->aoMs = r.aoMs;
        s->values = r.values;
        s->snippet = viewSnippet(job, t, *s);
        return publish(job, [&](State& st) { st.samples.push_back(std::move(s)); });
    };
    // One session, a job per candidate (a tuned fit's factors applied by the runner to the make-peers values).
    std::vector<EngineJob> jobs;
    for (const EngineCandidate* c : cands)
        jobs.push_back({0, engineJobValues(*c, t, job.radius), job.frames, c->scale, nullptr});
    const std::vector<EngineResult> res = runner.run(jobs);
    for (size_t i = 0; i < cands.size(); ++i) {
        if (res[i].hung) throw Error("the browser hung on " + cands[i]->label + " past its time limit");
        if (!add(*cands[i], res[i])) return;
    }
}

} // namespace ssao
