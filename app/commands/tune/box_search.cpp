#include "commands/tune/box_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ssao {

namespace {

constexpr int kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
constexpr double kWall = 0.02;  // a value within this share of its range's end sits at the wall
constexpr double kBasin = 0.25; // a second start at least this far from the best (unit box, max norm)
constexpr int kWidenings = 3;   // each by the range's span: up to 4x the span in all

// The radical inverse of i in `base`, shifted by `offset` (a scrambled Halton coordinate).
double halton(int i, int base, double offset) {
    double f = 1, r = 0;
    for (int n = i; n > 0; n /= base)
        f /= base, r += f * (n % base);
    return std::fmod(r + offset, 1.0);
}

struct Box {
    std::vector<BoxDim> d;
    double unit(size_t j, double v) const {
        const BoxDim& b = d[j];
        if (!(b.hi > b.lo)) return 0.5;
        return b.log ? std::log(v / b.lo) / std::log(b.hi / b.lo) : (v - b.lo) / (b.hi - b.lo);
    }
    double value(size_t j, double u) const {
        const BoxDim& b = d[j];
        return b.log ? b.lo * std::exp(u * std::log(b.hi / b.lo)) : b.lo + u * (b.hi - b.lo);
    }
};

bool better(double a, double b) {
    return std::isfinite(a) && (!std::isfinite(b) || a < b);
}

// Rounds of coordinate search from x (score `best`): each dimension over `grid` values of a bracket
// that starts as its whole range and halves every round, centred on the best value so far.
double coordinateSearch(const Box& box, std::vector<double>& x, double best, const BatchScorer& score,
                        const BoxSearchOptions& o, int rounds, int& batches, const std::function<void()>& tick) {
    std::vector<double> lo(x.size()), hi(x.size());
    for (size_t j = 0; j < x.size(); ++j)
        lo[j] = 0, hi[j] = 1; // unit coordinates
    for (int round = 0; round < rounds; ++round)
        for (size_t j = 0; j < x.size(); ++j) {
            std::vector<std::vector<double>> cands;
            for (int i = 0; i < o.grid; ++i) {
                cands.push_back(x);
                cands.back()[j] = box.value(j, lo[j] + (hi[j] - lo[j]) * i / double(std::max(1, o.grid - 1)));
            }
            const std::vector<double> s = score(cands);
            ++batches;
            for (size_t c = 0; c < cands.size() && c < s.size(); ++c)
                if (better(s[c], best)) best = s[c], x[j] = cands[c][j];
            const double u = std::clamp(box.unit(j, x[j]), 0.0, 1.0), half = (hi[j] - lo[j]) / 4.0;
            lo[j] = std::max(0.0, u - half), hi[j] = std::min(1.0, u + half);
            if (tick) tick();
        }
    return best;
}

} // namespace

int boxSearchBatches(size_t dims, const BoxSearchOptions& o) {
    return 1 + 2 * o.rounds * int(dims) + kWidenings * int(dims);
}

BoxResult boxSearch(const std::vector<BoxDim>& dims, double startScore, const BatchScorer& score,
                    const BoxSearchOptions& o, const std::function<void()>& tick) {
    Box box{dims};
    const size_t n = dims.size();
    BoxResult r;
    std::vector<double> start(n);
    for (size_t j = 0; j < n; ++j)
        start[j] = dims[j].start;
    // 1: the box, sampled; the start is one of the candidates, already scored.
    std::vector<std::vector<double>> pts = {start};
    const int samples = int(6 * n + 2);
    for (int i = 1; i <= samples; ++i) {
        std::vector<double> p(n);
        for (size_t j = 0; j < n; ++j)
            p[j] = box.value(j, halton(i, kPrimes[j % 12], 0.5 * double(j) / double(n + 1)));
        pts.push_back(p);
    }
    std::vector<double> s = {startScore};
    const std::vector<double> got = score({pts.begin() + 1, pts.end()});
    ++r.batches;
    s.insert(s.end(), got.begin(), got.end());
    s.resize(pts.size(), NAN);
    if (tick) tick();
    std::vector<size_t> order(pts.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return better(s[a], s[b]); });
    std::vector<size_t> from = {order[0]};
    for (size_t i : order) { // the best start of another basin
        if (!std::isfinite(s[i])) break;
        double far = 0;
        for (size_t j = 0; j < n; ++j)
            far = std::max(far, std::abs(box.unit(j, pts[i][j]) - box.unit(j, pts[order[0]][j])));
        if (far >= kBasin) {
            from.push_back(i);
            break;
        }
    }
    // 2: a coordinate search from each start; the best end wins.
    r.x = start, r.score = startScore;
    for (size_t f : from) {
        std::vector<double> x = pts[f];
        const double end = coordinateSearch(box, x, s[f], score, o, o.rounds, r.batches, tick);
        if (better(end, r.score) || (f == from[0] && !better(r.score, end))) r.score = end, r.x = x;
    }
    // 3: walls: widen the range of each dimension that ended at one (by its span, as far as allowed),
    // and search once more; up to kWidenings times while a wall holds the best point.
    for (int w = 0; w < kWidenings; ++w) {
        bool widened = false;
        for (size_t j = 0; j < n; ++j) {
            BoxDim& b = box.d[j];
            const double u = box.unit(j, r.x[j]);
            const double span = b.log ? std::log(b.hi / b.lo) : b.hi - b.lo;
            if (u <= kWall && b.allowLo < b.lo)
                b.lo = std::max(b.allowLo, b.log ? b.lo * std::exp(-span) : b.lo - span), widened = true;
            if (u >= 1 - kWall && b.allowHi > b.hi)
                b.hi = std::min(b.allowHi, b.log ? b.hi * std::exp(span) : b.hi + span), widened = true;
        }
        if (!widened) break;
        r.score = coordinateSearch(box, r.x, r.score, score, o, 1, r.batches, tick);
    }
    for (size_t j = 0; j < n; ++j) {
        const double u = box.unit(j, r.x[j]);
        const BoxDim& b = box.d[j];
        r.walls.push_back(u <= kWall ? -1 : u >= 1 - kWall ? 1 : 0);
        r.atLimit.push_back((u <= kWall && !(b.allowLo < b.lo)) || (u >= 1 - kWall && !(b.allowHi > b.hi)));
        r.lo.push_back(b.lo), r.hi.push_back(b.hi);
    }
    return r;
}

} // namespace ssao
