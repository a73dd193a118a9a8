#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>

using namespace ssao;
using ssaotest::writeTemp;

namespace {

std::string base64(const std::vector<unsigned char>& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        unsigned v =
            in[i] << 16 | (i + 1 < in.size() ? in[i + 1] << 8 : 0) | (i + 2 < in.size() ? in[i + 2] : 0);
        out += t[(v >> 18) & 63];
        out += t[(v >> 12) & 63];
        out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? t[v & 63] : '=';
    }
    return out;
}

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
        EXPECT_FLOAT_EQ(v.position.y, 2.0f); // node translation applied
        // No NORMAL: flat normal of the counter-clockwise face (0,0,0),(1,0,0),(0,0,-1) is +y.
        EXPECT_NEAR(v.normal.y, 1.0f, 1e-6f);
    }
    EXPECT_FALSE(s.camera.has_value());
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
    EXPECT_EQ(s.triangleCount(), 16732u); // instanced triangles listed in shared/scenes/README.md
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
    EXPECT_NE(errorOf(writeTemp("cycle.gltf",
                                patched(R"("mesh":0,"translation":[0,2,0])", R"("mesh":0,"children":[0])")))
                  .find("node 0 is its own ancestor"),
              std::string::npos);
    // Two nodes sharing a child is legal instancing; 30 levels of it is 2^30 instances.
    std::string nodes = R"("nodes":[)";
    for (int i = 0; i < 30; ++i)
        nodes += R"({"children":[)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
    nodes += R"({"mesh":0}],)";
    const std::string blowup =
        errorOf(writeTemp("blowup.gltf", patched(R"("nodes":[{"mesh":0,"translation":[0,2,0]}],)", nodes)));
    EXPECT_NE(blowup.find("node instances"), std::string::npos) << blowup;
    // Every vertex at one point: no extent to scale a radius by.
    EXPECT_NE(errorOf(writeTemp("point.gltf", patched(R"("translation":[0,2,0])", R"("scale":[0,0,0])")))
                  .find("no extent"),
              std::string::npos);
}
