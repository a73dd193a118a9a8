// Closed shells (scene/closed_shells.h): only triangles of closed, consistently wound shells of
// non-zero volume may have a side culled, and the side follows the shell's orientation.
#include "scene/closed_shells.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace ssao;

namespace {

// Triangles as corner positions; each corner its own vertex unless `shared` welds them in the
// index buffer too (the classifier must weld by position either way).
struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    void add(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (const glm::vec3& p : {a, b, c}) {
            indices.push_back(uint32_t(vertices.size()));
            vertices.push_back({p, glm::vec3(0, 0, 1)});
        }
    }
    size_t triangles() const { return indices.size() / 3; }
};

// A box's 12 triangles, counter-clockwise seen from outside (outward normals), or inside-out.
void addBox(Mesh& m, glm::vec3 lo, glm::vec3 hi, bool inward = false, int skipFace = -1) {
    auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    // Faces as corner quads a b c d, counter-clockwise from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; ++f) {
        if (f == skipFace) continue;
        const glm::vec3 a = corner(faces[f][0]), b = corner(faces[f][1]), c = corner(faces[f][2]), d = corner(faces[f][3]);
        if (inward) {
            m.add(a, c, b), m.add(a, d, c);
        } else {
            m.add(a, b, c), m.add(a, c, d);
        }
    }
}

std::vector<ShellFacing> classify(const Mesh& m) { return classifyShells(m.vertices, m.indices, 0, m.triangles()); }

size_t count(const std::vector<ShellFacing>& f, ShellFacing v) { return size_t(std::count(f.begin(), f.end(), v)); }

} // namespace

TEST(ClosedShells, ABoxWithUnsharedCornersIsOneOutwardShell) {
    Mesh m;
    addBox(m, glm::vec3(-1), glm::vec3(1));
    const auto f = classify(m);
    ASSERT_EQ(f.size(), 12u);
    EXPECT_EQ(count(f, ShellFacing::Outward), 12u); // welded by position: every edge has its twin
}

TEST(ClosedShells, AnInsideOutBoxIsInward) {
    Mesh m;
    addBox(m, glm::vec3(0), glm::vec3(2, 1, 3), true);
    EXPECT_EQ(count(classify(m), ShellFacing::Inward), 12u);
}

TEST(ClosedShells, AnOpenBoxGetsNoCulling) {
    // A box without its top: the camera can look in and see the inner (back) faces.
    Mesh m;
    addBox(m, glm::vec3(-1), glm::vec3(1), false, 3);
    EXPECT_EQ(count(classify(m), ShellFacing::Open), 10u);
}

TEST(ClosedShells, EachShellOfARangeIsJudgedOnItsOwn) {
    Mesh m;
    addBox(m, glm::vec3(0), glm::vec3(1));                 // 0-11 outward
    addBox(m, glm::vec3(5), glm::vec3(6), true);           // 12-23 inside out
    addBox(m, glm::vec3(-5), glm::vec3(-4), false, 0);     // 24-33 open
    addBox(m, glm::vec3(1e4f), glm::vec3(1e4f + 0.01f));   // 34-45: small and far from the others
    const auto f = classify(m);
    ASSERT_EQ(f.size(), 46u);
    for (size_t t = 0; t < 12; ++t) EXPECT_EQ(f[t], ShellFacing::Outward) << t;
    for (size_t t = 12; t < 24; ++t) EXPECT_EQ(f[t], ShellFacing::Inward) << t;
    for (size_t t = 24; t < 34; ++t) EXPECT_EQ(f[t], ShellFacing::Open) << t;
    for (size_t t = 34; t < 46; ++t) EXPECT_EQ(f[t], ShellFacing::Outward) << t;
}

TEST(ClosedShells, OneFlippedTriangleOpensTheShell) {
    // Inconsistent winding (CAD exports): its edges run the same way as their neighbours'.
    Mesh m;
    addBox(m, glm::vec3(-1), glm::vec3(1));
    std::swap(m.indices[1], m.indices[2]);
    EXPECT_EQ(count(classify(m), ShellFacing::Open), 12u);
}

TEST(ClosedShells, ASheetAndItsReversedCopyHaveNoInside) {
    // Closed and consistent by its edges, but of zero volume: both sides are visible.
    Mesh m;
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
    m.add(a, b, c), m.add(a, c, d);
    m.add(a, c, b), m.add(a, d, c);
    EXPECT_EQ(count(classify(m), ShellFacing::Open), 4u);
}

TEST(ClosedShells, BoxesSharingAnEdgeAreNonManifoldThere) {
    // Two boxes touching along one edge: it is used four times, so neither is trusted.
    Mesh m;
    addBox(m, glm::vec3(0), glm::vec3(1));
    addBox(m, glm::vec3(1, 1, 0), glm::vec3(2, 2, 1));
    EXPECT_EQ(count(classify(m), ShellFacing::Open), 24u);
}

TEST(ClosedShells, ACollapsedTriangleNeitherOpensNorJoinsTheShell) {
    Mesh m;
    addBox(m, glm::vec3(-1), glm::vec3(1));
    m.add(glm::vec3(-1), glm::vec3(-1), glm::vec3(1, -1, -1)); // two corners at one position
    const auto f = classify(m);
    EXPECT_EQ(count(f, ShellFacing::Outward), 12u);
    EXPECT_EQ(f[12], ShellFacing::Open);
}

TEST(ClosedShells, ARangeIsAnalysedAlone) {
    // Two halves of one box in two ranges (two materials): each half is open.
    Mesh m;
    addBox(m, glm::vec3(-1), glm::vec3(1));
    const auto a = classifyShells(m.vertices, m.indices, 0, 6);
    const auto b = classifyShells(m.vertices, m.indices, 18, 6);
    EXPECT_EQ(count(a, ShellFacing::Open), 6u);
    EXPECT_EQ(count(b, ShellFacing::Open), 6u);
    const auto whole = classifyShells(m.vertices, m.indices, 0, 12);
    EXPECT_EQ(count(whole, ShellFacing::Outward), 12u);
}

TEST(ClosedShells, BadRangesAreAllOpenNeverARead) {
    Mesh m;
    addBox(m, glm::vec3(-1), glm::vec3(1));
    EXPECT_EQ(count(classifyShells(m.vertices, m.indices, 3, 12), ShellFacing::Open), 12u); // past the end
    m.indices[4] = 1000;                                                                      // no such vertex
    EXPECT_EQ(count(classify(m), ShellFacing::Open), 12u);
    EXPECT_TRUE(classifyShells(m.vertices, m.indices, 0, 0).empty());
}
