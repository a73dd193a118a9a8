#include "techniques/noise/blue_noise.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace ssao {

namespace {

// Energy of every cell from the set points, with a toroidal Gaussian (Ulichney 1993, σ = 1.5).
struct Energy {
    int n;
    std::vector<float> kernel; // n x n, indexed by toroidal offset
    std::vector<float> e;
    explicit Energy(int size) : n(size), kernel(size_t(size) * size), e(size_t(size) * size, 0.0f) {
        const float sigma = 1.5f;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const int dx = std::min(x, n - x), dy = std::min(y, n - y);
                kernel[size_t(y) * n + x] = std::exp(-float(dx * dx + dy * dy) / (2.0f * sigma * sigma));
            }
    }
    void add(int idx, float sign) {
        const int px = idx % n, py = idx / n;
        for (int y = 0; y < n; ++y) {
            const float* krow = &kernel[size_t((y - py + n) % n) * n];
            float* erow = &e[size_t(y) * n];
            for (int x = 0; x < n; ++x) {
                const int kx = x - px;
                erow[x] += sign * krow[kx < 0 ? kx + n : kx];
            }
        }
    }
    // The tightest cluster (highest energy among set cells) or the largest void (lowest among empty).
    int extreme(const std::vector<uint8_t>& set, bool wantSet) const {
        int best = -1;
        for (size_t i = 0; i < e.size(); ++i) {
            if (bool(set[i]) != wantSet) continue;
            if (best < 0 || (wantSet ? e[i] > e[size_t(best)] : e[i] < e[size_t(best)])) best = int(i);
        }
        return best;
    }
};

} // namespace

std::vector<uint32_t> voidAndCluster(int size, uint32_t seed) {
    const int n = std::max(size, 2), total = n * n;
    std::vector<uint32_t> rank(size_t(total), 0);
    // Initial binary pattern: ~10 % random points, relaxed until the tightest cluster is the
    // largest void (the points are evenly spread).
    std::mt19937 rng(seed);
    std::vector<uint8_t> set(size_t(total), 0);
    Energy en(n);
    const int ones = std::max(1, total / 10);
    for (int placed = 0; placed < ones;) {
        const int i = int(rng() % uint32_t(total));
        if (set[size_t(i)]) continue;
        set[size_t(i)] = 1, en.add(i, 1.0f), ++placed;
    }
    for (int iter = 0; iter < 4 * total; ++iter) {
        const int cluster = en.extreme(set, true);
        set[size_t(cluster)] = 0, en.add(cluster, -1.0f);
        const int hole = en.extreme(set, false);
        set[size_t(hole)] = 1, en.add(hole, 1.0f);
        if (hole == cluster) break;
    }
    const std::vector<uint8_t> initial = set;
    const Energy initialEnergy = en;
    // Phase 1: remove the tightest clusters from the initial pattern, ranks ones-1 .. 0.
    for (int r = ones - 1; r >= 0; --r) {
        const int cluster = en.extreme(set, true);
        set[size_t(cluster)] = 0, en.add(cluster, -1.0f);
        rank[size_t(cluster)] = uint32_t(r);
    }
    // Phases 2 and 3: from the initial pattern, fill the largest voids, ranks ones .. total-1.
    set = initial, en = initialEnergy;
    for (int r = ones; r < total; ++r) {
        const int hole = en.extreme(set, false);
        set[size_t(hole)] = 1, en.add(hole, 1.0f);
        rank[size_t(hole)] = uint32_t(r);
    }
    return rank;
}

const std::vector<float>& blueNoise64Rg() {
    static const std::vector<float> tex = [] {
        const int n = kBlueNoiseSize, total = n * n;
        const std::vector<uint32_t> r = voidAndCluster(n, 1u), g = voidAndCluster(n, 2u);
        std::vector<float> out(size_t(total) * 2);
        for (int i = 0; i < total; ++i) {
            out[size_t(i) * 2] = (float(r[size_t(i)]) + 0.5f) / float(total);
            out[size_t(i) * 2 + 1] = (float(g[size_t(i)]) + 0.5f) / float(total);
        }
        return out;
    }();
    return tex;
}

} // namespace ssao
