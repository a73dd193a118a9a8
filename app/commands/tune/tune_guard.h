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
    std::string baseline;           // what `before` is when there were several ("as shipped"); "" one
};

FitVerdict judgeFit(const std::vector<HeldOutScore>& scores);

// A web engine's tune has two baselines on the same held-out views: the engine as its package ships
// it, and its defaults with every length from R. The fit is judged against the better of the two
// over all held-out views (the lower `before`), named in `baseline`: a tune that beats the rescaled
// defaults but not what the user already has is overfit.
FitVerdict judgeAgainstBetter(const std::vector<HeldOutScore>& shipped, const std::vector<HeldOutScore>& fromR);

// The one line of each outcome (no "ssaolab: error/warning:" prefix): refused, saved anyway, and
// saved while some scenes got worse. `out` is the preset file.
std::string refusalText(const FitVerdict& v, const std::string& out);
std::string overfitSavedText(const FitVerdict& v, const std::string& out);
std::string worseScenesText(const FitVerdict& v);

} // namespace ssao
