// The explorer's "Front" tab as state and answers, without drawing (view/panels/ui_front.cpp draws it):
// when the live reference of the view is finished, measure the candidates on it in the background
// (front/front_measurer.h); answer "cheapest at <= this error" and "most accurate at <= this time"
// relative to the current setting, and the budget box's "best within X ms / at most E". The y axis
// is a choice: the still frame's RMSE, or the motion score along the camera path through the view
// (front/front_motion.h); the answers and the front follow it. Once ssaolab's candidates are
// measured, the web engines run in Chromium (front/engine_front.h): their points join the still
// front; the answers stay among settings that can be applied.
#pragma once
#include "front/engine_front.h"
#include "front/front_measurer.h"
#include "front/front_motion.h"
#include "settings/preset_store.h"
#include "view/frame/frame_driver.h"

#include <string>

namespace ssao {

class FrontPanel {
  public:
    enum class Axis { Still, Motion };

    // `wake` (may be empty) is called from the motion path's tracing thread, `engineWake` from the
    // engines' thread when a result arrives: the loop sleeps otherwise.
    explicit FrontPanel(const std::string& shaderDir, std::function<void()> wake = {},
                        std::function<void()> engineWake = {})
        : m_(shaderDir), motion_(shaderDir, std::move(wake)), engines_(std::move(engineWake)) {}

    // Once per UI frame after the main render: starts (when the reference is finished), continues
    // (steps for `budgetMs`) or cancels (the view changed) the measurement. `sceneFile`: the
    // scene's spec (the engines load a glTF file; "builtin:..." they cannot).
    void update(const Settings& current, const PresetStore& store, FrameDriver& frames,
                const std::shared_ptr<const Scene>& scene, const std::string& sceneFile = "",
                double budgetMs = 20.0);

    bool active = false; // the tab has been opened: from then on the front is measured in the background
    bool paused = false;
    double budgetMs = 0, maxError = 0; // the budget box (0 = not set)
    Axis axis = Axis::Still;
    CameraPathSpec motionPath;                    // bench --motion's path by default
    int motionMaxWidth = 320, motionMaxHeight = 180; // the motion size: the view's, fit inside this
    std::string motionCacheDir = referenceCacheDir(); // the path's references ("" = not cached)
    // The y axis's name: "RMSE" or "motion score sqrt(RMSE^2 + instability^2)".
    std::string axisName() const;
    // Why nothing is being measured ("waiting for the reference (42%)"); "" while measuring or done.
    const std::string& waiting() const { return waiting_; }

    const FrontMeasurer& measurer() const { return m_; }
    const FrontMotion& motion() const { return motion_; }
    EngineFront& engines() { return engines_; }
    const EngineFront& engines() const { return engines_; }
    // Where the engines' tuned settings are read from: the user's preset folder's engines/.
    static std::string tunedDir(const PresetStore& store);
    // The points on the chosen axis: the still ones, or those with a motion score too (score set).
    const std::vector<FrontPoint>& points() const { return points_; }
    size_t currentIndex() const;  // the "current" point, npos until measured
    size_t baselineIndex() const; // the baseline's point, npos until measured
    // Relative to the current point: the fastest whose score is at most the current's, and the most
    // accurate whose time is at most the current's (other than the current itself, never an
    // engine's: an answer is applied); npos if none.
    size_t cheapestAtMostCurrentError() const;
    size_t mostAccurateWithinCurrentTime() const;
    // The budget box: the most accurate within budgetMs, and/or the fastest at most maxError (no engine's).
    size_t bestForBudget() const;
    double referenceNoise() const; // the reference's noise floor (RMS of its standard error)

  private:
    void updateMotion(const FrameDriver& frames, const std::shared_ptr<const Scene>& scene, unsigned sceneVersion);
    void compose(); // points_ from the measurers, on the chosen axis

    FrontMeasurer m_;
    FrontMotion motion_;
    EngineFront engines_;
    std::vector<FrontPoint> points_;
    std::vector<Candidate> candidates_;
    std::string candidatesKey_;
    std::string waiting_;
};

} // namespace ssao
