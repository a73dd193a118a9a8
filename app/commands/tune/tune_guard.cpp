#include "commands/tune/tune_guard.h"

#include <cmath>
#include <cstdio>

namespace ssao {

FitVerdict judgeFit(const std::vector<HeldOutScore>& scores) {
    FitVerdict v;
    double before = 0, after = 0;
    int views = 0;
    for (const HeldOutScore& s : scores) {
        if (s.views <= 0) continue;
        before += s.before * s.views, after += s.after * s.views, views += s.views;
        if (s.after > s.before) v.worse.push_back(s.scene);
    }
    if (views == 0) return v;
    v.before = std::sqrt(before / views), v.after = std::sqrt(after / views);
    v.overfit = after > before;
    return v;
}

FitVerdict judgeAgainstBetter(const std::vector<HeldOutScore>& shipped, const std::vector<HeldOutScore>& fromR) {
    FitVerdict a = judgeFit(shipped), b = judgeFit(fromR);
    a.baseline = "as shipped", b.baseline = "with lengths from R";
    return b.before < a.before ? b : a; // ties: the package's own settings
}

namespace {
std::string against(const FitVerdict& v) {
    return v.baseline.empty() ? "" : " against the engine " + v.baseline;
}
std::string rise(const FitVerdict& v) {
    char b[96];
    std::snprintf(b, sizeof b, " rose %.4f -> %.4f", v.before, v.after);
    return "held-out " + v.metric + b + against(v);
}
std::string list(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}
} // namespace

std::string refusalText(const FitVerdict& v, const std::string& out) {
    return "the fit does not generalise: " + rise(v) + " (worse on " + list(v.worse) + "); " + out +
           " not saved (add --save-overfit to save it anyway)";
}

std::string overfitSavedText(const FitVerdict& v, const std::string& out) {
    return "saved an OVERFIT preset to " + out + " (--save-overfit): " + rise(v) + " (worse on " + list(v.worse) +
           "); it fits its training views, not the scenes it never saw";
}

std::string worseScenesText(const FitVerdict& v) {
    char b[96];
    std::snprintf(b, sizeof b, " fell %.4f -> %.4f overall", v.before, v.after);
    return "held-out " + v.metric + b + against(v) + ", but rose on " + list(v.worse);
}

} // namespace ssao
