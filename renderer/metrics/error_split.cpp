#include "metrics/error_split.h"

#include <cmath>
#include <stdexcept>

namespace ssao {

const char* const kSharesHowToRead =
    "shares of the total squared error, summing to 1: technique = mean((AO-oracle)^2), screen = "
    "mean((oracle-truth)^2), interaction = 2 mean((AO-oracle)(oracle-truth)), each over mean((AO-truth)^2); a "
    "large negative interaction means the technique's error cancels the screen's: the technique's RMSE then "
    "overstates what its settings can fix";

namespace {
void setShares(ErrorShares& s) {
    if (!(s.mseTotal > 0.0)) return; // NaN shares: nothing to share out
    s.technique = s.mseTechnique / s.mseTotal;
    s.screen = s.mseScreen / s.mseTotal;
}
} // namespace

ErrorShares errorShares(const SplitImages& in) {
    if (in.width < 0 || in.height < 0) throw std::invalid_argument("errorShares: negative image size");
    const size_t n = size_t(in.width) * size_t(in.height);
    if (n > 0 && (!in.test || !in.oracle || !in.reference))
        throw std::invalid_argument("errorShares: the test, oracle and reference images are required");
    ErrorShares s;
    double sumE = 0, sumT = 0, sumS = 0, sumTS = 0;
    for (size_t i = 0; i < n; ++i) {
        if ((in.geometry && !(in.geometry[i] > 0.0f)) || (in.exclude && in.exclude[i] > 0.0f)) continue;
        const double ao = std::isfinite(in.test[i]) ? double(in.test[i]) : 1.0;
        const double t = ao - double(in.oracle[i]), sc = double(in.oracle[i]) - double(in.reference[i]);
        const double e = ao - double(in.reference[i]);
        sumE += e * e, sumT += t * t, sumS += sc * sc, sumTS += t * sc;
        ++s.pixels;
    }
    if (s.pixels == 0) return s;
    const double p = double(s.pixels);
    s.mseTotal = sumE / p, s.mseTechnique = sumT / p, s.mseScreen = sumS / p, s.meanCross = sumTS / p;
    setShares(s);
    if (s.mseTotal > 0.0) s.interaction = 2.0 * s.meanCross / s.mseTotal;
    return s;
}

ErrorShares sharesOfMse(double mseTotal, double mseTechnique, double mseScreen) {
    ErrorShares s;
    s.mseTotal = mseTotal, s.mseTechnique = mseTechnique, s.mseScreen = mseScreen;
    s.meanCross = 0.5 * (mseTotal - mseTechnique - mseScreen);
    setShares(s);
    if (s.mseTotal > 0.0) s.interaction = 1.0 - s.technique - s.screen;
    return s;
}

nlohmann::json sharesJson(const ErrorShares& s) {
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
    return {{"technique", num(s.technique)},
            {"screen", num(s.screen)},
            {"interaction", num(s.interaction)},
            {"how_to_read", kSharesHowToRead}};
}

} // namespace ssao
