#include "scene/closed_shells.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

struct Edge {
    uint64_t key; // (min(a, b) x ids + max(a, b)) x 2 + (a < b) for the edge a -> b of welded ids
    uint32_t tri;
};

// LSD radix sort by key, 11 bits a pass, as many passes as keys below `bound` need: linear in
// the edges, where a comparison sort is n log n over a CAD draw's millions of edges.
void radixSort(std::vector<Edge>& v, uint64_t bound) {
    std::vector<Edge> tmp(v.size());
    for (int shift = 0; shift < 64 && (bound >> shift) != 0; shift += 11) {
        size_t count[2049] = {};
        for (const Edge& e : v) ++count[((e.key >> shift) & 2047) + 1];
        for (int i = 0; i < 2048; ++i) count[i + 1] += count[i];
        for (const Edge& e : v) tmp[count[(e.key >> shift) & 2047]++] = e;
        v.swap(tmp);
    }
}

} // namespace

uint64_t weldHash(const glm::vec3& p) {
    auto bits = [](float f) {
        uint32_t u;
        std::memcpy(&u, &f, 4);
        return u == 0x80000000u ? 0u : u;
    };
    uint64_t hash = uint64_t(bits(p.x)) * 73856093u ^ uint64_t(bits(p.y)) * 19349663u ^ uint64_t(bits(p.z)) * 83492791u;
    hash ^= hash >> 33, hash *= 0xff51afd7ed558ccdull, hash ^= hash >> 33;
    hash *= 0xc4ceb9fe1a85ec53ull, hash ^= hash >> 33;
    return hash;
}

namespace {

// Weld: one id per corner, one per distinct position (an open-addressing table keyed by its bits,
// -0 as +0), each vertex looked up once; `ids` is how many there are.
std::vector<uint32_t> weld(const std::vector<Vertex>& vertices, const uint32_t* corner, size_t corners, uint32_t lo,
                           uint32_t hi, uint32_t& ids) {
    const size_t span = size_t(hi - lo) + 1;
    std::vector<uint32_t> weldOf(span, UINT32_MAX);
    size_t tableSize = 16;
    while (tableSize < 2 * span) tableSize *= 2;
    std::vector<uint32_t> table(tableSize, UINT32_MAX); // a representative vertex per slot
    std::vector<uint32_t> idOfSlot(tableSize);
    auto bits = [](float f) {
        uint32_t u;
        std::memcpy(&u, &f, 4);
        return u == 0x80000000u ? 0u : u;
    };
    ids = 0;
    std::vector<uint32_t> w(corners);
    for (size_t i = 0; i < corners; ++i) {
        uint32_t& id = weldOf[corner[i] - lo];
        if (id == UINT32_MAX) {
            const glm::vec3& p = vertices[corner[i]].position;
            const uint32_t x = bits(p.x), y = bits(p.y), z = bits(p.z);
            size_t slot = size_t(weldHash(p)) & (tableSize - 1);
            for (;; slot = (slot + 1) & (tableSize - 1)) {
                if (table[slot] == UINT32_MAX) {
                    table[slot] = corner[i], idOfSlot[slot] = ids++;
                    break;
                }
                const glm::vec3& q = vertices[table[slot]].position;
                if (bits(q.x) == x && bits(q.y) == y && bits(q.z) == z) break;
            }
            id = idOfSlot[slot];
        }
        w[i] = id;
    }
    return w;
}

// Edges of every triangle that keeps three distinct corners (one that collapses under welding
// covers no pixel: it stays Open and joins no shell), keyed by the undirected edge and then its
// direction, so that an edge's uses sort next to each other. A collapsed triangle is marked bad.
std::vector<Edge> sortedEdges(const std::vector<uint32_t>& w, size_t triangles, uint32_t ids,
                              std::vector<uint8_t>& bad) {
    std::vector<Edge> edges;
    edges.reserve(w.size());
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t c[3] = {w[3 * t], w[3 * t + 1], w[3 * t + 2]};
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) {
            bad[t] = 1;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = c[k], b = c[(k + 1) % 3];
            edges.push_back({(uint64_t(std::min(a, b)) * ids + std::max(a, b)) << 1 | uint64_t(a < b), t});
        }
    }
    radixSort(edges, uint64_t(ids) * ids * 2);
    return edges;
}

// Closed and consistent: each undirected edge used exactly twice, once in each direction (a
// manifold edge of two triangles that run along it opposite ways). Triangles so joined form
// one shell; a triangle on any other edge is marked bad.
UnionFind joinShells(const std::vector<Edge>& edges, size_t triangles, std::vector<uint8_t>& bad) {
    UnionFind shells(triangles);
    for (size_t j = 0; j < edges.size();) {
        size_t end = j + 1;
        while (end < edges.size() && edges[end].key >> 1 == edges[j].key >> 1) ++end;
        if (end - j == 2 && (edges[j].key & 1) != (edges[j + 1].key & 1)) {
            shells.unite(edges[j].tri, edges[j + 1].tri);
        } else {
            for (size_t k = j; k < end; ++k) bad[edges[k].tri] = 1;
        }
        j = end;
    }
    return shells;
}

// Per shell: any bad triangle opens it; the signed volume (divergence theorem, relative to
// one of the shell's own corners so that a small part far from the others keeps its digits)
// says which side faces out.
void orientShells(const std::vector<Vertex>& vertices, const uint32_t* corner, size_t triangles, UnionFind& shells,
                  const std::vector<uint8_t>& bad, std::vector<ShellFacing>& out) {
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
}

} // namespace

std::vector<ShellFacing> classifyShells(const std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices,
                                        size_t first, size_t triangles) {
    std::vector<ShellFacing> out(triangles, ShellFacing::Open);
    if (triangles == 0 || triangles > kShellMaxTriangles || first + 3 * triangles > indices.size()) return out;
    const uint32_t* corner = indices.data() + first;
    const size_t corners = 3 * triangles;
    uint32_t lo = UINT32_MAX, hi = 0;
    for (size_t i = 0; i < corners; ++i) lo = std::min(lo, corner[i]), hi = std::max(hi, corner[i]);
    if (hi >= vertices.size()) return out; // the loader rejects these; stay safe regardless

    uint32_t ids = 0;
    const std::vector<uint32_t> w = weld(vertices, corner, corners, lo, hi, ids);
    std::vector<uint8_t> bad(triangles, 0);
    const std::vector<Edge> edges = sortedEdges(w, triangles, ids, bad);
    UnionFind shells = joinShells(edges, triangles, bad);
    orientShells(vertices, corner, triangles, shells, bad, out);
    return out;
}

} // namespace ssao
