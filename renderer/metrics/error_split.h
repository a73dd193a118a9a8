// The error against the truth split through the screen-space oracle so that the parts add up.
// With e = AO - truth, t = AO - oracle (the technique's part) and s = oracle - truth (the screen's),
// e = t + s, so mean(e^2) = mean(t^2) + mean(s^2) + 2 mean(t s): the technique's and the screen's
// RMSEs alone do not add to the total (a technique whose error cancels the screen's has two large
// parts and a small total). The shares of the total squared error do: technique + screen +
// interaction = 1, the interaction negative where the two errors cancel. Pure CPU code.
#pragma once
#include <nlohmann/json.hpp>

#include <limits>

namespace ssao {

struct ErrorShares {
    long pixels = 0; // geometry pixels counted (as computeErrorMetrics: ambiguous ones left out)
    // mean(e^2), mean(t^2), mean(s^2), mean(t s) over those pixels.
    double mseTotal = 0, mseTechnique = 0, mseScreen = 0, meanCross = 0;
    // Of mean(e^2): mean(t^2), mean(s^2), 2 mean(t s); they sum to 1. NaN when mean(e^2) is 0.
    double technique = std::numeric_limits<double>::quiet_NaN();
    double screen = std::numeric_limits<double>::quiet_NaN();
    double interaction = std::numeric_limits<double>::quiet_NaN();
};

// Single-channel images of one view, row-major, width * height values each.
struct SplitImages {
    int width = 0, height = 0;
    const float* test = nullptr;      // the AO under test; NaN/inf count as 1.0, as every metric does
    const float* oracle = nullptr;    // the screen-space oracle of the view
    const float* reference = nullptr; // the truth
    const float* geometry = nullptr;  // > 0 where the pixel shows geometry; null = all
    const float* exclude = nullptr;   // > 0 where the truth is ambiguous (left out); null = none
};

// The additive split of one view. Throws std::invalid_argument when an image is missing or a size
// is negative.
ErrorShares errorShares(const SplitImages& in);

// The shares from the three mean squared errors alone (a benchmark row, or MSEs averaged over
// views, each over the same pixels): the interaction is what the other two leave of the total.
ErrorShares sharesOfMse(double mseTotal, double mseTechnique, double mseScreen);

// How to read the shares, one line (metrics.json, the report, the explorer's tooltip).
extern const char* const kSharesHowToRead;

// {"technique": .., "screen": .., "interaction": .., "how_to_read": ..}; NaN → null.
nlohmann::json sharesJson(const ErrorShares& s);

} // namespace ssao
