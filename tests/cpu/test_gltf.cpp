#include "scene/load/builtin_scenes.h"
#include "scene/load/gltf_loader.h"
#include "scene/scene.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>

using namespace ssao;
using ssaotest::base64;
using ssaotest::writeTemp;

namespace {


// One triangle (no normals) with uint8 indices under a translated node, as a .gltf with a data URI.
std::string triangleGltf(const std::string& extra = "") {
    std::vector<unsigned char> bytes(36 + 4, 0);
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    std::memcpy(bytes.data(), pos, 36);
    bytes[36] = 0, bytes[37] = 1, bytes[38] = 2;
    return R"({"asset":{"version":"2.0"},)" + extra + R"("scene":0,"scenes":[{"nodes":[0]}],
      "nodes":[{"mesh":0,"translation":[0,2,0]}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
      "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.25,1,1]}}],
      "buffers":[{"byteLength":40,"uri":"data:application/octet-stream;base64,)" +
           base64(bytes) + R"("}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":3}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,-1],"max":[1,0,0]},
                   {"bufferView":1,"componentType":5121,"count":3,"type":"SCALAR"}]})";
}

std::string errorOf(const std::string& path) {
    try {
        loadGltf(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Gltf, Uint8IndicesNodeTransformMaterialAndFlatNormals) {
    Scene s = loadGltf(writeTemp("tri.gltf", triangleGltf()));
    ASSERT_EQ(s.triangleCount(), 1u);
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
    for (auto& v : s.vertices) {
        EXPECT_DOUBLE_EQ(s.toWorld(v.position).y, 2.0); // node translation applied (file coordinates)
        // No NORMAL: flat normal of the counter-clockwise face (0,0,0),(1,0,0),(0,0,-1) is +y.
        EXPECT_NEAR(v.normal.y, 1.0f, 1e-6f);
    }
    EXPECT_FALSE(s.camera.has_value());
}

TEST(Gltf, AMeshFarFromTheOriginKeepsItsDetailInTheSceneFrame) {
    // The triangle (0,0,0),(1e-3,0,0),(0,0,-1e-3) translated 1e6 units: as float file coordinates
    // its corners would be 1/16 unit apart (one point); relative to the scene's double-precision
    // origin they keep their millimetre.
    std::string text = triangleGltf();
    const std::string from = "\"translation\":[0,2,0]";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "\"translation\":[1000000,2,-500000],\"scale\":[0.001,0.001,0.001]");
    const Scene s = loadGltf(writeTemp("far_tri.gltf", text));
    EXPECT_NEAR(s.origin.x, 1e6, 1.0);
    EXPECT_NEAR(s.origin.z, -5e5, 1.0);
    EXPECT_NEAR(2.0f * s.bounds.radius(), std::sqrt(2.0f) * 1e-3f, 1e-7f);
    for (const Vertex& v : s.vertices)
        EXPECT_LT(glm::length(v.position), 1e-3f); // small numbers: full float precision
    EXPECT_NEAR(s.toWorld(s.vertices[1].position).x - s.toWorld(s.vertices[0].position).x, 1e-3, 1e-9);
    // --camera takes file coordinates; the renderer gets them relative to the origin.
    Camera base;
    const Camera c = parseCamera("1000000,2.01,-499999.99,1000000,2,-500000", base, s.origin);
    EXPECT_NEAR(c.eye.y, 2.01f - float(s.origin.y), 1e-6f);
    EXPECT_NEAR(glm::length(c.eye - c.target), std::sqrt(2e-4f), 1e-6f); // not 1/16-unit steps
    EXPECT_NEAR(cameraToFile(c, s).eye.x, 1e6f, 0.1f);
}

TEST(Gltf, RequiredDracoIsAClearError) {
    std::string p = writeTemp(
        "draco.gltf",
        triangleGltf(
            R"("extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"],)"));
    EXPECT_NE(errorOf(p).find("KHR_draco_mesh_compression"), std::string::npos) << errorOf(p);
}

TEST(Gltf, MissingAndCorruptFilesAreClearErrors) {
    EXPECT_NE(errorOf("/nonexistent/scene.gltf").find("scene file not found"), std::string::npos);
    std::string e = errorOf(writeTemp("corrupt.gltf", "{ this is not json"));
    EXPECT_NE(e.find("cannot load glTF"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
    e = errorOf(writeTemp("corrupt.glb", std::string("glTF\x02\0\0\0garbage", 15)));
    EXPECT_NE(e.find("cannot load glTF"), std::string::npos) << e;
    e = errorOf(writeTemp("empty.gltf", R"({"asset":{"version":"2.0"}})"));
    EXPECT_NE(e.find("no triangles"), std::string::npos) << e;
}

TEST(Gltf, CornellBoxLoadsWithItsCamera) {
    Scene s = loadGltf(std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf");
    // Instanced triangles listed in shared/scenes/README.md: 16732, of which the glass sphere's
    // 8318 are BLEND and skipped by default (test_transparent.cpp).
    EXPECT_EQ(s.triangleCount(), 16732u - 8318u);
    EXPECT_EQ(s.materials.blend, 8318u);
    ASSERT_TRUE(s.camera.has_value());
    EXPECT_NEAR(s.bounds.min.y, -5.05f, 1e-3f);
    EXPECT_NEAR(s.bounds.max.x, 5.05f, 1e-3f);
    for (auto& v : s.vertices)
        ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
}

TEST(Gltf, EveryThirdPartySceneLoads) {
    const auto files = ssaotest::sharedSceneFiles();
    for (const auto& f : files) {
        Scene s = loadGltf(f.string());
        EXPECT_GT(s.triangleCount(), 1000u) << f;
        EXPECT_TRUE(std::isfinite(s.bounds.radius())) << f;
    }
    EXPECT_GE(files.size(), 8u);
}

TEST(BuiltinScenes, AllBuildAndUnknownNamesAreListed) {
    for (auto& name : builtinSceneNames()) {
        Scene s = makeBuiltinScene(name);
        EXPECT_GT(s.triangleCount(), 0u);
        EXPECT_TRUE(s.camera.has_value());
    }
    try {
        makeBuiltinScene("nope");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("showcase, plane, corner"), std::string::npos);
    }
}

namespace {
// The triangle above with one JSON value replaced: `from` must occur exactly once.
std::string patched(const std::string& from, const std::string& to, const std::string& extra = "") {
    std::string g = triangleGltf(extra);
    const size_t at = g.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return g.replace(at, from.size(), to);
}
} // namespace

TEST(GltfHostile, OffsetsAndCountsThatWrapAroundAreRefused) {
    // Values near 2^64 made the naive `offset + size <= length` check wrap and pass: a read far
    // outside the buffer (a crash, or garbage geometry).
    const std::pair<const char*, const char*> cases[] = {
        {R"("byteOffset":0,"byteLength":36)", R"("byteOffset":18446744073708765184,"byteLength":36)"},
        {R"("byteOffset":0,"byteLength":36)", R"("byteOffset":0,"byteLength":18446744073709551615)"},
        {R"("componentType":5126,"count":3)", R"("componentType":5126,"count":4611686018427387908)"},
        {R"("componentType":5126,"count":3)",
         R"("componentType":5126,"byteOffset":18446744073709551608,"count":3)"},
    };
    int i = 0;
    for (const auto& [from, to] : cases) {
        const std::string e = errorOf(writeTemp("wrap" + std::to_string(i++) + ".gltf", patched(from, to)));
        EXPECT_TRUE(e.find("outside its buffer") != std::string::npos ||
                    e.find("past the end") != std::string::npos ||
                    e.find("cannot load glTF") != std::string::npos)
            << to << ": " << e;
    }
}

TEST(GltfHostile, BufferUrisStayInsideTheScenesFolder) {
    const std::string dir = std::string(SSAOLAB_TEST_TMP) + "/uri_jail/scene";
    std::filesystem::create_directories(dir + "/sub");
    std::ofstream(dir + "/../secret.bin") << std::string(40, 'x');
    {
        std::ofstream bin(dir + "/sub/ok.bin", std::ios::binary);
        const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
        bin.write(reinterpret_cast<const char*>(pos), sizeof pos);
        const unsigned char idx[4] = {0, 1, 2, 0};
        bin.write(reinterpret_cast<const char*>(idx), sizeof idx);
    }
    const std::string data = R"("uri":"data:application/octet-stream;base64,)";
    auto withUri = [&](const std::string& name, const std::string& uri) {
        std::string g = triangleGltf();
        const size_t a = g.find(data), b = g.find('"', a + data.size());
        g.replace(a, b + 1 - a, "\"uri\":\"" + uri + "\"");
        std::ofstream(dir + "/" + name) << g;
        return errorOf(dir + "/" + name);
    };
    EXPECT_NE(withUri("up.gltf", "../secret.bin").find("outside the scene's folder"), std::string::npos);
    const std::string abs = withUri("abs.gltf", "/etc/passwd");
    EXPECT_TRUE(abs.find("outside the scene's folder") != std::string::npos ||
                abs.find("File not found") != std::string::npos)
        << abs;
    EXPECT_NE(withUri("dir.gltf", "sub").find("not a regular file"), std::string::npos);
    EXPECT_EQ(withUri("inside.gltf", "sub/../sub/ok.bin"), ""); // inside, however it is spelled
    ::mkfifo((dir + "/pipe.bin").c_str(), 0600);                // reading it would block forever
    EXPECT_NE(withUri("fifo.gltf", "pipe.bin").find("not a regular file"), std::string::npos);
    ::mkfifo((dir + "/pipe.gltf").c_str(), 0600);
    EXPECT_NE(errorOf(dir + "/pipe.gltf").find("not a regular"), std::string::npos);
    EXPECT_NE(errorOf(dir).find("not a regular"), std::string::npos); // a folder given as the scene
}

TEST(GltfHostile, CyclesDepthSharedNodesAndDegenerateGeometry) {
    // A root that lists itself as its child: refused as a node with a second parent (the root list).
    EXPECT_NE(errorOf(writeTemp("cycle.gltf",
                                patched(R"("mesh":0,"translation":[0,2,0])", R"("mesh":0,"children":[0])")))
                  .find("node 0 is a scene root and also listed elsewhere"),
              std::string::npos);
    // A node listing the same child twice, 30 levels deep, was 2^30 instances from a 2 KB file.
    // glTF allows one parent per node: the first repeated child is refused, by name.
    std::string nodes = R"("nodes":[)";
    for (int i = 0; i < 30; ++i)
        nodes += R"({"children":[)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
    nodes += R"({"mesh":0}],)";
    const std::string blowup =
        errorOf(writeTemp("blowup.gltf", patched(R"("nodes":[{"mesh":0,"translation":[0,2,0]}],)", nodes)));
    EXPECT_NE(blowup.find("node 1 has two parents (0 and 0)"), std::string::npos) << blowup;
    // Two parents sharing a child, and a root that is also a child.
    auto withNodes = [](const std::string& roots, const std::string& nodes) {
        std::string g = triangleGltf();
        const std::string r0 = R"("scenes":[{"nodes":[0]}])", n0 = R"("nodes":[{"mesh":0,"translation":[0,2,0]}])";
        g.replace(g.find(r0), r0.size(), R"("scenes":[{"nodes":)" + roots + "}]");
        g.replace(g.find(n0), n0.size(), R"("nodes":)" + nodes);
        return g;
    };
    const std::string shared = errorOf(
        writeTemp("shared.gltf", withNodes("[0,1]", R"([{"children":[2]},{"children":[2]},{"mesh":0}])")));
    EXPECT_NE(shared.find("node 2 has two parents (0 and 1)"), std::string::npos) << shared;
    const std::string rootChild =
        errorOf(writeTemp("rootchild.gltf", withNodes("[0,1]", R"([{"children":[1]},{"mesh":0}])")));
    EXPECT_NE(rootChild.find("node 1 is a scene root and also listed elsewhere"), std::string::npos) << rootChild;
    // A cycle away from the roots is never walked: the scene loads what the roots reach.
    EXPECT_EQ(errorOf(writeTemp("island.gltf", withNodes("[0]", R"([{"mesh":0},{"children":[2]},{"children":[1]}])"))),
              "");
    // Every vertex at one point: no extent to scale a radius by.
    EXPECT_NE(errorOf(writeTemp("point.gltf", patched(R"("translation":[0,2,0])", R"("scale":[0,0,0])")))
                  .find("no extent"),
              std::string::npos);
}

TEST(GltfHostile, OneAccessorInManyPrimitivesMeetsTheBudget) {
    // Legal glTF: one accessor drawn by many primitives. 4,000 primitives of a 65k-vertex accessor
    // expanded to 262 M vertices and exhausted memory; now the budget refuses it before appending.
    std::string prims;
    for (int i = 0; i < 40; ++i)
        prims += std::string(i ? "," : "") + R"({"attributes":{"POSITION":0},"indices":1})";
    const std::string path =
        writeTemp("manyprims.gltf", patched(R"([{"attributes":{"POSITION":0},"indices":1,"material":0}])",
                                            "[" + prims + "]"));
    EXPECT_EQ(loadGltf(path).triangleCount(), 40u); // within the default budget
    const SceneBudget saved = sceneBudget();
    setSceneBudget({25, saved.bytes});
    const std::string e = errorOf(path);
    setSceneBudget(saved);
    EXPECT_NE(e.find("past the budget of 25 triangles (raise it with ssaolab --max-triangles N)"), std::string::npos)
        << e;
}

TEST(GltfHostile, ImagesAreNeverDecoded) {
    // A JPEG header claiming 23000x23000 (4 GB to decode) and an image whose bufferView lies far
    // outside its buffer: ssaolab uses no textures, so neither is decoded and the scene loads.
    std::vector<unsigned char> jpeg = {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 0x08, 0x59, 0xD8, 0x59, 0xD8, 0x03,
                                       0x01, 0x22, 0x00, 0x02, 0x11, 0x01, 0x03, 0x11, 0x01, 0xFF, 0xD9};
    const std::string images =
        R"("images":[{"uri":"data:image/jpeg;base64,)" + base64(jpeg) + R"("},{"bufferView":2,"mimeType":"image/png"}],)";
    std::string g = patched(R"({"buffer":0,"byteOffset":36,"byteLength":3}])",
                            R"({"buffer":0,"byteOffset":36,"byteLength":3},{"buffer":0,"byteOffset":36,"byteLength":100000}])",
                            images);
    const std::string path = writeTemp("images.gltf", g);
    EXPECT_EQ(errorOf(path), "");
}
