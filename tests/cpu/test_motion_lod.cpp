// The clustered mesh drawn while the camera moves (scene/gpu/motion_lod.h): fewer triangles, only the
// scene's own vertices, both sides of thin walls, cut-outs whole, and the pixel test of a cell.
#include "scene/load/gltf_loader.h"
#include "scene/gpu/motion_lod.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace ssao;

namespace {

// An n x n grid of quads on z = z0 over [0, size]^2 with normal (0, 0, nz), as one draw.
void addGrid(Scene& s, int n, float size, float z0, float nz, bool mask = false) {
    const uint32_t base = uint32_t(s.vertices.size());
    Draw d;
    d.firstIndex = uint32_t(s.indices.size());
    d.mask = mask;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            s.vertices.push_back({glm::vec3(size * float(x) / float(n), size * float(y) / float(n), z0), glm::vec3(0, 0, nz)});
    auto at = [&](int x, int y) { return base + uint32_t(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            s.indices.insert(s.indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1)});
            s.indices.insert(s.indices.end(), {at(x, y), at(x + 1, y + 1), at(x, y + 1)});
        }
    d.indexCount = uint32_t(s.indices.size()) - d.firstIndex;
    s.draws.push_back(d);
    s.computeBounds();
}

Bounds boundsOf(const Scene& s, const std::vector<uint32_t>& indices, uint32_t first, uint32_t count) {
    Bounds b;
    for (uint32_t i = first; i < first + count; ++i) b.add(s.vertices[indices[i]].position);
    return b;
}

} // namespace

TEST(MotionLod, AFineGridKeepsItsExtentWithAFractionOfItsTriangles) {
    Scene s;
    addGrid(s, 256, 1.0f, 0.0f, 1.0f); // quads 1/256 wide, cells 1/32: 8 x 8 quads a cell
    const MotionLod lod = buildMotionLod(s, 1.0f / 32.0f);
    ASSERT_EQ(lod.first.size(), 1u);
    EXPECT_LT(lod.triangles() * 20, s.triangleCount()) << lod.triangles() << " of " << s.triangleCount();
    EXPECT_GT(lod.triangles(), 0u);
    std::set<std::array<uint32_t, 3>> seen;
    for (size_t t = 0; t < lod.triangles(); ++t) {
        std::array<uint32_t, 3> k{lod.indices[3 * t], lod.indices[3 * t + 1], lod.indices[3 * t + 2]};
        for (uint32_t v : k) {
            ASSERT_LT(v, s.vertices.size()); // one of the scene's own vertices
            EXPECT_EQ(s.vertices[v].position.z, 0.0f); // on the surface
        }
        EXPECT_TRUE(k[0] != k[1] && k[1] != k[2] && k[0] != k[2]);
        std::sort(k.begin(), k.end());
        EXPECT_TRUE(seen.insert(k).second) << "a triangle twice";
    }
    // The clustered grid spans the same square to within a cell.
    const Bounds b = boundsOf(s, lod.indices, 0, lod.count[0]);
    EXPECT_LE(b.min.x, 1.0f / 32.0f);
    EXPECT_LE(b.min.y, 1.0f / 32.0f);
    EXPECT_GE(b.max.x, 1.0f - 1.0f / 32.0f);
    EXPECT_GE(b.max.y, 1.0f - 1.0f / 32.0f);
    // Clustered triangles keep the grid's facing (+z, counter-clockwise seen from above).
    for (size_t t = 0; t < lod.triangles(); ++t) {
        const glm::vec3 a = s.vertices[lod.indices[3 * t]].position, b2 = s.vertices[lod.indices[3 * t + 1]].position,
                        c = s.vertices[lod.indices[3 * t + 2]].position;
        EXPECT_GE(glm::cross(b2 - a, c - a).z, 0.0f);
    }
}

TEST(MotionLod, BothSidesOfAWallThinnerThanACellStay) {
    Scene s;
    addGrid(s, 64, 1.0f, 0.0f, 1.0f);
    // The other side 1/100 of a cell below, facing down, in the same draw (one material).
    Scene back;
    addGrid(back, 64, 1.0f, -0.0001f, -1.0f);
    const uint32_t offset = uint32_t(s.vertices.size());
    s.vertices.insert(s.vertices.end(), back.vertices.begin(), back.vertices.end());
    for (uint32_t i : back.indices) s.indices.push_back(i + offset);
    s.draws[0].indexCount = uint32_t(s.indices.size());
    s.computeBounds();
    const MotionLod lod = buildMotionLod(s, 1.0f / 16.0f);
    size_t up = 0, down = 0;
    for (size_t t = 0; t < lod.triangles(); ++t) {
        const float nz = s.vertices[lod.indices[3 * t]].normal.z;
        for (int k = 1; k < 3; ++k) EXPECT_EQ(s.vertices[lod.indices[3 * t + k]].normal.z, nz); // never mixed
        (nz > 0 ? up : down)++;
    }
    EXPECT_GT(up, 0u);
    EXPECT_EQ(up, down); // mirror images: the same cells on both sides
}

TEST(MotionLod, CutOutDrawsAreKeptWholeAndDrawsStayApart) {
    Scene s;
    addGrid(s, 64, 1.0f, 0.0f, 1.0f);
    addGrid(s, 64, 1.0f, 0.5f, 1.0f, /*mask=*/true);
    const MotionLod lod = buildMotionLod(s, 1.0f / 8.0f);
    ASSERT_EQ(lod.first.size(), 2u);
    EXPECT_LT(lod.count[0], s.draws[0].indexCount);
    EXPECT_EQ(lod.count[1], s.draws[1].indexCount);
    for (uint32_t i = 0; i < lod.count[0]; ++i) EXPECT_LT(lod.indices[lod.first[0] + i], 65u * 65u); // draw 0's vertices only
    for (uint32_t i = 0; i < lod.count[1]; ++i)
        EXPECT_EQ(lod.indices[lod.first[1] + i], s.indices[s.draws[1].firstIndex + i]);
}

TEST(MotionLod, SmallScenesAndDegenerateCellsGetNoCopy) {
    Scene s;
    addGrid(s, 16, 1.0f, 0.0f, 1.0f); // 512 triangles
    EXPECT_TRUE(motionLodsFor(s).empty());
    EXPECT_EQ(buildMotionLod(s, 0.0f).cell, 0.0f);
    EXPECT_EQ(buildMotionLod(s, std::nanf("")).cell, 0.0f);
    EXPECT_TRUE(buildMotionLod(s, -1.0f).indices.empty());
    Scene big;
    addGrid(big, 200, 1.0f, 0.0f, 1.0f); // 80k triangles; cells of 1/96 .. 1/768 of the diagonal
    const std::vector<MotionLod> lods = motionLodsFor(big);
    // 1/96 of the diagonal is 1/68 a side (~3 quads): kept; 1/384 is 1/271, finer than a quad: it
    // would keep every triangle, so the levels stop before it.
    ASSERT_GE(lods.size(), 1u);
    EXPECT_LT(lods.size(), 5u);
    for (size_t i = 0; i < lods.size(); ++i) {
        EXPECT_LE(double(lods[i].triangles()), 0.75 * double(big.triangleCount()));
        if (i > 0) {
            EXPECT_NEAR(lods[i].cell / lods[i - 1].cell, std::sqrt(0.5f), 1e-3f); // each level: the cell / sqrt 2
            EXPECT_GT(lods[i].triangles(), lods[i - 1].triangles());   // and keeps more
        }
    }
}

TEST(MotionLod, ACellsPixelsFollowTheNearestDepthOfTheBounds) {
    Bounds b;
    b.add(glm::vec3(-1, -1, -1)), b.add(glm::vec3(1, 1, 1));
    Camera c;
    c.eye = glm::vec3(0, 0, 11), c.target = glm::vec3(0), c.fovYDeg = 90.0f; // nearest depth 10, tan 45 = 1
    EXPECT_NEAR(motionLodCellPx(0.1f, b, c, 200), 0.1f * 200.0f / 20.0f, 1e-5f);
    // The same through the matrices the G-buffer's constants hold (each draw's own level).
    EXPECT_NEAR(motionLodCellPx(0.1f, b, c.view(), c.projection(1.0f)[1][1], false, 200), 1.0f, 1e-5f);
    Bounds far; // the same box 10 units farther: half the pixels
    far.add(glm::vec3(-1, -1, -11)), far.add(glm::vec3(1, 1, -9));
    EXPECT_NEAR(motionLodCellPx(0.1f, far, c.view(), c.projection(1.0f)[1][1], false, 200), 0.5f, 1e-5f);
    c.eye = glm::vec3(0, 0, 0.5f); // inside
    EXPECT_TRUE(std::isinf(motionLodCellPx(0.1f, b, c, 200)));
    c.eye = glm::vec3(0, 0, 11);
    c.projectionKind = Projection::Orthographic; // spans 2 |target - eye| tan(fov / 2) = 22 units
    EXPECT_NEAR(motionLodCellPx(0.1f, b, c, 220), 1.0f, 1e-4f);
    EXPECT_NEAR(motionLodCellPx(0.1f, far, c.view(), c.projection(1.0f)[1][1], true, 220), 1.0f, 1e-4f); // depth aside
    EXPECT_TRUE(std::isinf(motionLodCellPx(0.1f, Bounds{}, c, 220)));
}

TEST(MotionLod, SharedScenesWithManyTrianglesGetACopyThatDrawsFewer) {
    size_t built = 0;
    for (const auto& f : ssaotest::sharedSceneFiles()) {
        const Scene s = loadGltf(f.string());
        const std::vector<MotionLod> lods = motionLodsFor(s);
        for (const MotionLod& lod : lods)
            std::printf("%s: %zu triangles -> %zu with cells of %g (%.1f %%)\n", f.filename().string().c_str(),
                        s.triangleCount(), lod.triangles(), lod.cell,
                        100.0 * double(lod.triangles()) / double(s.triangleCount()));
        if (s.triangleCount() < kMotionLodMinTriangles) {
            EXPECT_TRUE(lods.empty());
            continue;
        }
        built += !lods.empty();
        for (const MotionLod& lod : lods) {
            EXPECT_EQ(lod.first.size(), s.draws.size());
            EXPECT_LE(double(lod.triangles()), 0.75 * double(s.triangleCount()));
            for (size_t d = 0; d < s.draws.size(); ++d) // a large material keeps triangles (none vanishes whole)
                if (s.draws[d].indexCount >= 3000) {
                    EXPECT_GT(lod.count[d], 0u) << f << " draw " << d;
                }
        }
    }
    EXPECT_EQ(built, 3u) << "2CylinderEngine, FlightHelmet and ReciprocatingSaw (121k, 94k, 198k triangles) get copies";
}
