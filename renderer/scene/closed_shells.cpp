#include "scene/closed_shells.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ssao {

namespace {

struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]]; // path halving
        return x;
    }
    void unite(uint32_t a, uint32_t b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

bool lessPosition(const glm::vec3& a, const glm::vec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

struct Edge {
    uint64_t key; // welded ids a << 32 | b of the directed edge a -> b
    uint32_t tri;
};

uint64_t edgeKey(uint32_t a, uint32_t b) { return uint64_t(a) << 32 | b; }

} // namespace

std::vector<ShellFacing> classifyShells(const std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices,
                                        size_t first, size_t triangles) {
    std::vector<ShellFacing> out(triangles, ShellFacing::Open);
    if (triangles == 0 || triangles > kShellMaxTriangles || first + 3 * triangles > indices.size()) return out;
    const uint32_t* corner = indices.data() + first;
    const size_t corners = 3 * triangles;
    for (size_t i = 0; i < corners; ++i)
        if (corner[i] >= vertices.size()) return out; // the loader rejects these; stay safe regardless

    // Weld: the range's distinct vertices in position order; equal positions share one id.
    std::vector<uint32_t> used(corner, corner + corners);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::vector<uint32_t> byPosition(used.size());
    std::iota(byPosition.begin(), byPosition.end(), 0u);
    std::sort(byPosition.begin(), byPosition.end(), [&](uint32_t a, uint32_t b) {
        return lessPosition(vertices[used[a]].position, vertices[used[b]].position);
    });
    std::vector<uint32_t> weld(used.size());
    uint32_t id = 0;
    for (size_t k = 0; k < byPosition.size(); ++k) {
        if (k > 0 && lessPosition(vertices[used[byPosition[k - 1]]].position, vertices[used[byPosition[k]]].position))
            ++id;
        weld[byPosition[k]] = id;
    }
    std::vector<uint32_t> w(corners);
    for (size_t i = 0; i < corners; ++i)
        w[i] = weld[size_t(std::lower_bound(used.begin(), used.end(), corner[i]) - used.begin())];

    // Directed edges of every triangle that keeps three distinct corners (one that collapses
    // under welding covers no pixel: it stays Open and joins no shell).
    std::vector<uint8_t> bad(triangles, 0);
    std::vector<Edge> edges;
    edges.reserve(corners);
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t a = w[3 * t], b = w[3 * t + 1], c = w[3 * t + 2];
        if (a == b || b == c || a == c) {
            bad[t] = 1;
            continue;
        }
        edges.push_back({edgeKey(a, b), t});
        edges.push_back({edgeKey(b, c), t});
        edges.push_back({edgeKey(c, a), t});
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) { return x.key < y.key; });
    auto range = [&](uint64_t key) {
        return std::equal_range(edges.begin(), edges.end(), Edge{key, 0},
                                [](const Edge& x, const Edge& y) { return x.key < y.key; });
    };

    // Closed and consistent: each directed edge once, its reverse once (a manifold edge of two
    // triangles that run along it in opposite directions). Triangles so joined form one shell.
    UnionFind shells(triangles);
    for (size_t j = 0; j < edges.size();) {
        size_t end = j + 1;
        while (end < edges.size() && edges[end].key == edges[j].key) ++end;
        const uint64_t key = edges[j].key;
        const auto reverse = range(edgeKey(uint32_t(key & 0xffffffffu), uint32_t(key >> 32)));
        if (end - j != 1 || reverse.second - reverse.first != 1) {
            for (size_t k = j; k < end; ++k) bad[edges[k].tri] = 1;
        } else {
            shells.unite(edges[j].tri, reverse.first->tri);
        }
        j = end;
    }

    // Per shell: any bad triangle opens it; the signed volume (divergence theorem, relative to
    // one of the shell's own corners so that a small part far from the others keeps its digits)
    // says which side faces out.
    std::vector<uint8_t> open(triangles, 0);
    std::vector<double> volume(triangles, 0.0), scale(triangles, 0.0);
    for (uint32_t t = 0; t < triangles; ++t) open[shells.find(t)] |= bad[t];
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t root = shells.find(t);
        if (open[root]) continue;
        const glm::dvec3 o(vertices[corner[3 * root]].position);
        const glm::dvec3 p0 = glm::dvec3(vertices[corner[3 * t]].position) - o;
        const glm::dvec3 p1 = glm::dvec3(vertices[corner[3 * t + 1]].position) - o;
        const glm::dvec3 p2 = glm::dvec3(vertices[corner[3 * t + 2]].position) - o;
        const double v = glm::dot(p0, glm::cross(p1, p2));
        volume[root] += v;
        scale[root] += std::fabs(v);
    }
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t root = shells.find(t);
        // A shell of (near) zero volume - a sheet and its reversed copy - has no inside to hide
        // behind; leave it alone rather than trust the sign of rounding.
        if (open[root] || !(std::fabs(volume[root]) > 1e-6 * scale[root])) continue;
        out[t] = volume[root] > 0.0 ? ShellFacing::Outward : ShellFacing::Inward;
    }
    return out;
}

} // namespace ssao
