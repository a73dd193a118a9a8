#include "commands/tune/engine_tuner.h"

#include "commands/tune/box_search.h"

#include "engines/engine_snippet.h"
#include "measure/viewpoints.h"
#include "metrics/evaluate.h"
#include "cli/headless_runner.h"
#include "cli/progress_bar.h"
#include "reference/reference_cache.h"
#include "cli/scene_options.h"
#include "cli/cli_util.h"
#include "cli/view_radius.h"
#include "scene/view_fit.h"
#include "settings/preset.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ssao {

double meanOf(const std::vector<double>& v) {
    double s = 0;
    for (double x : v)
        s += x;
    return v.empty() ? std::numeric_limits<double>::quiet_NaN() : s / double(v.size());
}

namespace {

bool sameValues(const KnobSet& a, const KnobSet& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].p != b[i].p || a[i].value != b[i].value) return false;
    return true;
}

double meanMs(const std::vector<Sample>& v) {
    std::vector<double> ms;
    for (const Sample& x : v)
        ms.push_back(x.ms);
    return meanOf(ms);
}

bool trainOnly(const TuneView& v) {
    return v.role == TuneRole::Train;
}

bool every(const TuneView&) {
    return true;
}

} // namespace

EngineTuner::EngineTuner(const TuneOptions& o, EngineTable table, int w, int h)
    : o_(o), table_(std::move(table)), tools_(locateEngineTools(o.engine.modules, table_)), w_(w), h_(h) {}

EngineTuner::~EngineTuner() = default;

void EngineTuner::prepare() {
    std::vector<std::string> specs = o_.scenes;
    specs.insert(specs.end(), o_.heldOutScenes.begin(), o_.heldOutScenes.end());
    for (size_t si = 0; si < specs.size(); ++si) {
        scenes_.push_back(loadNamedScene(specs[si]));
        addViews(si, specs[si], si >= o_.scenes.size());
    }
}

void EngineTuner::measureDefaults() {
    const auto samples = measure({KnobSet{}}, every, 0, true);
    for (const Sample& s : samples[0])
        defaults_[s.view] = s.mse;
}

std::vector<Knob> EngineTuner::chooseKnobs() const {
    std::vector<Knob> knobs;
    for (const EngineParam& p : table_.params) {
        const bool named = std::find(o_.knobs.begin(), o_.knobs.end(), p.name) != o_.knobs.end();
        if (p.role == EngineParam::Role::Shape && (o_.knobs.empty() || named)) {
            const TuneView& v = views_[firstTrain()];
            knobs.push_back({&p, p.searchLo, p.searchHi, p.relative ? 1.0 : p.perRadius ? v.base.at(p.name) / std::pow(v.radius, p.perRadius)
                                                                                     : v.base.at(p.name)});
        }
    }
    for (const std::string& k : o_.knobs) {
        const EngineParam* p = table_.find(k);
        if (!p || p->role != EngineParam::Role::Shape)
            throw Error("--knob " + k + " is not a shape parameter of " + table_.engine + " (" + shapeNames() +
                        "; cost parameters are chosen by a budget, not fitted)");
    }
    return knobs;
}

double EngineTuner::trainScore() const {
    std::vector<double> v;
    for (const TuneView& view : views_)
        if (view.role == TuneRole::Train) v.push_back(defaults_.at(size_t(&view - views_.data())));
    return meanOf(v);
}

std::pair<double, double> EngineTuner::allowedRange(const Knob& k) const {
    double lo = k.p->log ? 1e-9 : -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    if (!k.p->range) return {lo, hi};
    lo = std::max(lo, 0.0);
    for (const TuneView& v : views_) {
        const double scale = k.p->relative ? v.base.at(k.p->name) : k.p->perRadius ? std::pow(v.radius, k.p->perRadius) : 1.0;
        if (!(scale > 0)) continue;
        lo = std::max(lo, k.p->range->first / scale), hi = std::min(hi, k.p->range->second / scale);
    }
    return {lo, hi};
}

std::vector<double> EngineTuner::trainScores(const std::vector<KnobSet>& cands) {
    searching_ = true; // a candidate the browser takes far too long on is dropped, not waited for
    const auto samples = measure(cands, trainOnly, 0, false);
    searching_ = false;
    std::vector<double> out;
    for (const auto& c : samples) {
        std::vector<double> mse;
        for (const Sample& s : c)
            mse.push_back(s.mse);
        out.push_back(meanOf(mse));
    }
    return out;
}

std::vector<std::string> EngineTuner::search(std::vector<Knob>& knobs, double best) {
    std::vector<BoxDim> dims;
    for (const Knob& k : knobs) {
        const auto [lo, hi] = allowedRange(k); // every value the search tries is one the engine's table accepts
        double a = std::max(k.p->searchLo, lo), b = std::min(k.p->searchHi, hi);
        if (!(a <= b)) { // the search range lies outside what the table accepts on these views: search that
            a = lo, b = hi;
            if (!(a <= b)) a = b = k.value; // nothing accepted on every view: the knob stays where it is
        }
        dims.push_back({a, b, k.p->log, lo, hi, k.value});
    }
    const BoxSearchOptions opt{o_.rounds, o_.grid};
    ProgressBar bar("  search " + std::to_string(knobs.size()) + " parameters of " + table_.title, !o_.quiet);
    int done = 0;
    const int total = boxSearchBatches(knobs.size(), opt);
    const BatchScorer score = [&](const std::vector<std::vector<double>>& pts) {
        std::vector<KnobSet> cands;
        for (const auto& p : pts) {
            cands.push_back(knobs);
            for (size_t j = 0; j < knobs.size(); ++j)
                cands.back()[j].value = p[j];
        }
        return trainScores(cands);
    };
    const BoxResult r = boxSearch(dims, best, score, opt, [&] { bar.update(std::min(1.0, double(++done) / total)); });
    bar.update(1);
    for (size_t j = 0; j < knobs.size(); ++j)
        knobs[j].value = r.x[j];
    std::vector<std::string> walls;
    const auto values = valuesFor(knobs, views_[firstTrain()]);
    for (size_t j = 0; j < knobs.size(); ++j) {
        if (r.walls[j] == 0) continue;
        char b[280];
        if (r.atLimit[j])
            std::snprintf(b, sizeof b, "%s = %.4g ended at the %s of what the table's range %s allows on every view: the "
                                       "optimum may lie beyond",
                          knobs[j].p->name.c_str(), values.at(knobs[j].p->name), r.walls[j] < 0 ? "bottom" : "top",
                          engineRangeText(*knobs[j].p).c_str());
        else
            std::snprintf(b, sizeof b, "%s = %.4g ended at the %s of its search range, widened 3 times by its span: the "
                                       "optimum may lie beyond",
                          knobs[j].p->name.c_str(), values.at(knobs[j].p->name), r.walls[j] < 0 ? "bottom" : "top");
        walls.push_back(b);
    }
    return walls;
}

std::vector<BudgetRung> EngineTuner::chooseCost(std::vector<Knob>& knobs) {
    const EngineTuneOptions& e = o_.engine;
    if (e.budgetMs <= 0 && e.budgetRatio <= 0) return {};
    std::vector<KnobSet> cands = {KnobSet{}};
    std::vector<double> factors;
    for (double f : {0.25, 0.5, 1.0, 2.0, 4.0}) {
        KnobSet c = knobs;
        for (const EngineParam& p : table_.params)
            if (p.scalesWithBudget) c.push_back({&p, 0, 0, scaledCost(p, f)});
        if (std::any_of(cands.begin() + 1, cands.end(), [&](const KnobSet& x) { return sameValues(x, c); })) continue;
        cands.push_back(c), factors.push_back(f);
    }
    ProgressBar bar("  time " + std::to_string(factors.size()) + " sample counts of " + table_.title, !o_.quiet);
    const auto samples = measure(cands, trainOnly, e.timingFrames, false);
    bar.update(1);
    const double budget = e.budgetMs > 0 ? e.budgetMs : e.budgetRatio * meanMs(samples[0]);
    std::vector<BudgetRung> rungs;
    size_t chosen = 1; // the cheapest when none fits
    for (size_t c = 1; c < cands.size(); ++c) {
        rungs.push_back({factors[c - 1], meanMs(samples[c]), budget, false});
        if (rungs.back().ms <= budget) chosen = c;
    }
    rungs[chosen - 1].chosen = true;
    knobs = cands[chosen];
    return rungs;
}

KnobSet EngineTuner::shippedKnobs() const {
    KnobSet out;
    for (const auto& [name, v] : shippedValues(table_))
        out.push_back({table_.find(name), 0, 0, v, true});
    return out;
}

std::vector<std::vector<Sample>> EngineTuner::finalMeasure(const std::vector<Knob>& tuned) {
    const int frames = o_.engine.timingFrames;
    auto out = measure({KnobSet{}, tuned, shippedKnobs()}, every, frames, false, true);
    std::vector<bool> full(views_.size(), false); // a job that reached the harness's cap is timed inside its spread by one frame
    for (const Sample& x : out[2])
        full[x.view] = x.timedFrames >= frames;
    out.push_back(measure({shippedKnobs()}, [&](const TuneView& v) { return full[size_t(&v - views_.data())]; }, frames, false)[0]);
    return out;
}

std::map<std::string, double> EngineTuner::valuesFor(const KnobSet& c, const TuneView& v) const {
    std::map<std::string, double> out;
    for (const Knob& k : c) {
        const double x = k.absolute ? k.value
                         : k.p->relative ? v.base.at(k.p->name) * k.value
                         : k.p->perRadius ? std::pow(v.radius, k.p->perRadius) * k.value
                                          : k.value;
        out[k.p->name] = exportedValue(k.p->type == EngineParam::Type::Integer ? std::round(x) : x);
    }
    return out;
}

int EngineTuner::sessions() const {
    int n = 0;
    for (const auto& r : runners_)
        n += r->sessions();
    return n;
}

int EngineTuner::batches() const {
    int n = 0;
    for (const auto& r : runners_)
        n += r->batches();
    return n;
}

void EngineTuner::addViews(size_t si, const std::string& spec, bool heldOutScene) {
    const Scene& sc = scenes_.back();
    const float radius = o_.radiusScene * 2.0f * sc.bounds.radius();
    ReferenceProvider provider(sc);
    std::vector<EngineView> engineViews;
    int k = 0;
    for (const auto& [name, cam] : viewpoints(heldOutScene ? defaultCamera(sc) : startCamera(o_.camera, sc), o_.views)) {
        const Camera c = effectiveCamera(cam, sc.bounds); // the clip planes ssaolab's renderer fits
        ProgressBar bar("  reference " + sc.name + " " + name, !o_.quiet);
        ReferenceImage ref = provider.get(c, w_, h_, {radius, o_.referenceRays}, [&](double f) { bar.update(f); });
        radius_.check(sc.name, name, ref, c, o_.radiusScene, 2.0 * sc.bounds.radius());
        const TuneRole role = heldOutScene ? TuneRole::HeldOutScene : k % 2 == 0 ? TuneRole::Train : TuneRole::HeldOutView;
        double oracleMse = std::numeric_limits<double>::quiet_NaN();
        if (role != TuneRole::Train) {
            ReferenceSettings os{radius, o_.referenceRays};
            os.visibility = ReferenceVisibility::Screen;
            ProgressBar ob("  oracle " + sc.name + " " + name, !o_.quiet);
            const ReferenceImage oracle = provider.get(c, w_, h_, os, [&](double f) { ob.update(f); });
            oracleMse = std::pow(evaluate(Image{oracle.width, oracle.height, 1, oracle.ao}, ref).metrics.rmse, 2);
        }
        views_.push_back({si, k, name, role, c, std::move(ref), {}, radius, k == (heldOutScene ? 0 : 1), oracleMse});
        engineViews.push_back({cameraToJson(cameraToFile(c, sc)), radius});
        ++k;
    }
    specs_.push_back(spec);
    if (const std::string w = radius_.line(sc.name); !w.empty()) printWarnings({w});
    runners_.push_back(std::make_unique<EngineRunner>(tools_, table_, spec, w_, h_, std::move(engineViews)));
}

std::vector<std::vector<Sample>> EngineTuner::measure(const std::vector<KnobSet>& cands, const std::function<bool(const TuneView&)>& want,
                                                      int frames, bool recordBase, bool keepImages) {
    std::vector<std::vector<Sample>> out(cands.size());
    for (size_t si = 0; si < runners_.size(); ++si) {
        std::vector<EngineJob> jobs;
        std::vector<std::pair<size_t, size_t>> of; // (candidate, view) of each job
        for (size_t c = 0; c < cands.size(); ++c)
            for (size_t v = 0; v < views_.size(); ++v)
                if (views_[v].scene == si && want(views_[v])) {
                    jobs.push_back({views_[v].index, valuesFor(cands[c], views_[v]), frames});
                    jobs.back().droppable = searching_;
                    jobs.back().group = searching_ ? int(c) : -1;
                    of.emplace_back(c, v);
                }
        if (jobs.empty()) continue;
        const std::vector<EngineResult> res = runners_[si]->run(jobs);
        std::vector<bool> hungCand(cands.size(), false);
        for (size_t j = 0; j < jobs.size(); ++j) {
            TuneView& view = views_[of[j].second];
            if (res[j].hung) { // a candidate the browser never finished: never the best; the baselines must finish
                if (recordBase || frames > 0)
                    throw Error(table_.title + " hung on " + scenes_[si].name + " " + view.viewpoint + " at settings the tune must measure");
                out[of[j].first].push_back({of[j].second, std::numeric_limits<double>::infinity(), NAN, nullptr});
                if (!hungCand[of[j].first]) hungCand[of[j].first] = true, ++hungJobs_; // a candidate, once a scene
                continue;
            }
            auto e = std::make_shared<Evaluation>(evaluate(res[j].ao, view.ref));
            if (e->metrics.nonFinite > 0) throw Error(table_.title + " returned non-finite AO on " + scenes_[si].name);
            if (recordBase) view.base = res[j].values;
            const double rmse = e->metrics.rmse;
            if (!(keepImages && view.shown)) e.reset();
            out[of[j].first].push_back({of[j].second, rmse * rmse, res[j].aoMs, std::move(e), res[j].timedFrames});
        }
    }
    return out;
}

double EngineTuner::scaledCost(const EngineParam& p, double f) const {
    double v = p.defaultValue * f;
    if (p.type == EngineParam::Type::Integer) v = std::max(1.0, std::round(v));
    return p.range ? std::clamp(v, p.range->first, p.range->second) : v;
}

size_t EngineTuner::firstTrain() const {
    for (size_t i = 0; i < views_.size(); ++i)
        if (views_[i].role == TuneRole::Train) return i;
    throw Error("no training view");
}

std::string EngineTuner::shapeNames() const {
    std::string s;
    for (const EngineParam& p : table_.params)
        if (p.role == EngineParam::Role::Shape) s += (s.empty() ? "shape parameters: " : ", ") + p.name;
    return s;
}

} // namespace ssao
