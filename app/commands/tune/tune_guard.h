// Whether a tuned preset generalises: `ssaolab tune` judges the fit on what it never fitted (the
// odd viewpoints of its training scenes and every viewpoint of each --held-out-scene). A fit that
// raises that held-out error is overfit: tune refuses to save it unless told to (--save-overfit),
// and names any scene it made worse while the whole got better.
#pragma once
#include <string>
#include <vector>

namespace ssao {

// One scene's held-out views: their mean geometry MSE before and after the fit.
struct HeldOutScore {
    std::string scene; // "builtin:corner", or "builtin:corner (held-out views)" for a training scene
    double before = 0, after = 0;
    int views = 0;
};

struct FitVerdict {
    std::string metric = "geometry RMSE"; // what the numbers are (the square root of the scores' mean)
    double before = 0, after = 0;   // `metric` over every held-out view
    bool overfit = false;           // after > before: the fit does not carry over
    std::vector<std::string> worse; // scenes whose held-out error rose
};

FitVerdict judgeFit(const std::vector<HeldOutScore>& scores);

// The one line of each outcome (no "ssaolab: error/warning:" prefix): refused, saved anyway, and
// saved while some scenes got worse. `out` is the preset file.
std::string refusalText(const FitVerdict& v, const std::string& out);
std::string overfitSavedText(const FitVerdict& v, const std::string& out);
std::string worseScenesText(const FitVerdict& v);

} // namespace ssao
