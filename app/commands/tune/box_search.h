// The derivative-free search `tune --engine` runs over an engine's shape parameters, pure: a box
// of parameters (each linear or log-spaced, with a range it may widen into), a batch scorer (one
// call scores many points: one browser session per scene), and the best point. A scrambled Halton
// sample of the box; a coordinate search (each parameter on a grid inside a bracket that halves
// every round) from the best start and from the best start of another basin; a parameter that ends
// at a wall of its range has it widened by its span, up to 3 times within its allowed range, each
// followed by one more round.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace ssao {

struct BoxDim {
    double lo = 0, hi = 1;            // the search range (log: both > 0)
    bool log = false;                 // grid and sample evenly in log(value)
    double allowLo = 0, allowHi = 0;  // how far the range may widen (what the engine accepts on every view)
    double start = 0;                 // the starting value (the engine's defaults)
};

struct BoxSearchOptions {
    int rounds = 3, grid = 7;
};

// Scores a batch of points (each one value per dimension); lower is better; NaN never wins.
using BatchScorer = std::function<std::vector<double>(const std::vector<std::vector<double>>&)>;

struct BoxResult {
    std::vector<double> x;      // the best point found (the start when nothing beat it)
    double score = 0;           // its score
    std::vector<int> walls;     // per dimension: -1 at the bottom of its final range, +1 at the top, 0 inside
    std::vector<bool> atLimit;  // per dimension: at a wall its allowed range does not let it move past
    std::vector<double> lo, hi; // the final ranges (widened where a wall moved)
    int batches = 0;            // scorer calls
};

// `startScore`: the start's score, already measured. `tick` (may be empty) after each batch.
BoxResult boxSearch(const std::vector<BoxDim>& dims, double startScore, const BatchScorer& score,
                    const BoxSearchOptions& o, const std::function<void()>& tick = {});
// The batches boxSearch makes at most for `dims` dimensions (a progress bar's length).
int boxSearchBatches(size_t dims, const BoxSearchOptions& o);

} // namespace ssao
