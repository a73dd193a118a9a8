// `tune --engine`'s search (commands/tune/engine_tune.h): the scenes' views and references, one engine
// runner per scene, and the measurements of candidate settings on them. A derivative-free search with
// restarts over the engine's shape parameters only (commands/tune/box_search.h); a time budget picks
// the sample counts afterwards (chooseCost), never the error.
#pragma once
#include "cli/view_radius.h"
#include "engines/engine_runner.h"
#include "engines/engine_table.h"
#include "commands/tune/tune_command.h"
#include "reference/reference_ao.h"
#include "metrics/evaluate.h"
#include "scene/scene.h"

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ssao {

// Which score a view counts in: fitted on; held out of a training scene; of a held-out scene.
enum class TuneRole { Train, HeldOutView, HeldOutScene };

struct TuneView {
    size_t scene;
    int index; // in its scene's runner
    std::string viewpoint;
    TuneRole role;
    Camera camera; // fitted clip planes, scene frame
    ReferenceImage ref;
    std::map<std::string, double> base; // what the engine ran with at its make-peers settings here
    float radius = 0;                   // R, scene units
    bool shown = false; // the scene's first held-out view: its images are kept for the report page
    // Held-out views: the screen-space oracle's MSE against ref (reference_ao.h: the same integral
    // over what one G-buffer holds), the error no screen-space AO can remove; NaN on training views.
    double oracleMse = std::numeric_limits<double>::quiet_NaN();
};

struct Knob {
    const EngineParam* p;
    // value: x the view's make-peers value when p->relative, x the view's R when p->perRadius, else the
    // value itself; `absolute`: the value itself whatever the row (the engine as its package ships it)
    double lo, hi, value;
    bool absolute = false;
};
using KnobSet = std::vector<Knob>; // empty: the make-peers settings

struct BudgetRung {
    double factor, ms, budget; // x the engine's default counts; training views' mean AO ms
    bool chosen;
};

struct Sample {
    size_t view;
    double mse, ms;
    std::shared_ptr<const Evaluation> eval; // the AO judged, on shown views when kept
    int timedFrames = 0;                    // EngineResult::timedFrames
};

double meanOf(const std::vector<double>& v);

class EngineTuner {
  public:
    EngineTuner(const TuneOptions& o, EngineTable table, int w, int h);
    ~EngineTuner();

    // Scenes (glTF files: the browser loads them), their viewpoints and references, one runner each.
    void prepare();
    // The make-peers settings on every view: what each ran with becomes its base.
    void measureDefaults();
    std::vector<Knob> chooseKnobs() const;
    double trainScore() const;
    // Derivative-free search with restarts over the shape knobs (commands/tune/box_search.h), log-
    // spaced where the row says (lengths and intensities), a wall widened as far as the table's range
    // holds on every view. Returns one line per knob that still ends at a wall ("may lie beyond").
    std::vector<std::string> search(std::vector<Knob>& knobs, double best);
    // The time budget's choice of the cost rows that scale with it: each rung multiplies them all by
    // one factor; the training views' mean AO time of each rung (timed, with the fitted shape) picks
    // the largest that fits. Returns the rungs measured, the chosen one marked; none without a budget.
    std::vector<BudgetRung> chooseCost(std::vector<Knob>& knobs);
    // The engine as its package ships it: every row the harness sets from R (lengths, and factors
    // on them) back at the table's default, verbatim; the rows that read the AO alone stay set.
    KnobSet shippedKnobs() const;
    // Every view, timed: [0] the defaults with lengths from R, [1] the tuned settings, [2] the engine
    // as shipped (the shown views' images kept), [3] as shipped again, on the views where [2] timed
    // every frame asked for (harness.js framesDone): the timing's own noise.
    std::vector<std::vector<Sample>> finalMeasure(const std::vector<Knob>& tuned);
    // The engine's value of each knob on a view.
    std::map<std::string, double> valuesFor(const KnobSet& c, const TuneView& v) const;

    const std::vector<TuneView>& views() const { return views_; }
    const TuneView& firstTrainView() const { return views_[firstTrain()]; }
    const std::vector<Scene>& scenes() const { return scenes_; }
    const EngineTable& table() const { return table_; }
    int sessions() const;
    int batches() const; // the browser's batches of jobs (the search's steps)
    // Candidates the browser hung on (EngineResult::hung): scored as never the best.
    int hungJobs() const { return hungJobs_; }
    std::string sceneSpec(size_t i) const { return specs_[i]; }

  private:
    void addViews(size_t si, const std::string& spec, bool heldOutScene);
    // Every candidate on every view `want` keeps, one browser session per scene; recordBase: each
    // view's base becomes what the engine ran with.
    std::vector<std::vector<Sample>> measure(const std::vector<KnobSet>& cands, const std::function<bool(const TuneView&)>& want,
                                             int frames, bool recordBase, bool keepImages = false);
    double scaledCost(const EngineParam& p, double f) const;
    // The training views' mean MSE of each candidate (one batch).
    std::vector<double> trainScores(const std::vector<KnobSet>& cands);
    bool searching_ = false; // measure()'s jobs are the search's candidates
    // The widest range in the knob's unit whose values stay inside the table's range on every view.
    std::pair<double, double> allowedRange(const Knob& k) const;
    size_t firstTrain() const;
    std::string shapeNames() const;

    const TuneOptions& o_;
    EngineTable table_;
    EngineTools tools_;
    int w_, h_;
    std::vector<Scene> scenes_;
    std::vector<std::string> specs_;
    std::vector<TuneView> views_;
    std::vector<std::unique_ptr<EngineRunner>> runners_;
    std::map<size_t, double> defaults_; // view -> MSE at the make-peers settings
    SceneRadiusWarnings radius_;        // R against what each view spans
    int hungJobs_ = 0;
};

} // namespace ssao
