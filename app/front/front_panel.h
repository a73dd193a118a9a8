// The explorer's "Front" tab as state and answers, without drawing (view/ui_front.cpp draws it):
// when the live reference of the view is finished, measure the candidates on it in the background
// (front/front_measurer.h); answer "cheapest at <= this error" and "most accurate at <= this time"
// relative to the current setting, and the budget box's "best within X ms / at most E".
#pragma once
#include "front/front_measurer.h"
#include "settings/preset_store.h"
#include "view/frame_driver.h"

#include <string>

namespace ssao {

class FrontPanel {
  public:
    explicit FrontPanel(std::string shaderDir) : m_(std::move(shaderDir)) {}

    // Once per UI frame after the main render: starts (when the reference is finished), continues
    // (steps for `budgetMs`) or cancels (the view changed) the measurement.
    void update(const Settings& current, const PresetStore& store, FrameDriver& frames,
                const std::shared_ptr<const Scene>& scene, double budgetMs = 20.0);

    bool active = false; // the tab has been opened: from then on the front is measured in the background
    bool paused = false;
    double budgetMs = 0, maxError = 0; // the budget box (0 = not set)
    // Why nothing is being measured ("waiting for the reference (42%)"); "" while measuring or done.
    const std::string& waiting() const { return waiting_; }

    const FrontMeasurer& measurer() const { return m_; }
    const std::vector<FrontPoint>& points() const { return m_.points(); }
    size_t currentIndex() const; // the "current" point, npos until measured
    // Relative to the current point: the fastest whose RMSE is at most the current's, and the most
    // accurate whose time is at most the current's (other than the current itself); npos if none.
    size_t cheapestAtMostCurrentError() const;
    size_t mostAccurateWithinCurrentTime() const;
    // The budget box: the most accurate within budgetMs, and/or the fastest at most maxError.
    size_t bestForBudget() const;
    double referenceNoise() const; // the reference's noise floor (RMS of its standard error)

  private:
    FrontMeasurer m_;
    std::vector<Candidate> candidates_;
    std::string candidatesKey_;
    std::string waiting_;
};

} // namespace ssao
