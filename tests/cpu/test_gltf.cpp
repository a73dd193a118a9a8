#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

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
