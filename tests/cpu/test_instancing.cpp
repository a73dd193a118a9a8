// EXT_mesh_gpu_instancing (scene/load/gltf_instancing.h): instances expanded into triangles within the
// budget, with each instance's T x R x S applied in the node's frame; required extensions that
// cannot be honoured refused by name, those that change no geometry accepted.
#include "lid_scene.h"
#include "scene/load/gltf_loader.h"
#include "scene/scene.h"
#include "test_util.h"

#include <gtest/gtest.h>

using namespace ssao;
using namespace ssaotest;

namespace {
// One triangle (0,0,0) (1,0,0) (0,1,0) on node 0 at translation (0, 0, 10), instanced by the given
// TRANSLATION / ROTATION / SCALE (float) lists; `count` overrides the accessors' counts.
nlohmann::json instanced(const std::vector<glm::vec3>& t, const std::vector<glm::vec4>& r, const std::vector<glm::vec3>& s) {
    std::vector<unsigned char> bin;
    auto put = [&](const void* p, size_t n) {
        const size_t at = bin.size();
        bin.insert(bin.end(), static_cast<const unsigned char*>(p), static_cast<const unsigned char*>(p) + n);
        return at;
    };
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array(), attrs = nlohmann::json::object();
    auto add = [&](const void* p, size_t n, size_t count, const char* type) {
        const size_t at = put(p, n);
        views.push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", n}});
        accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", 5126}, {"count", count}, {"type", type}});
        return accessors.size() - 1;
    };
    add(tri, sizeof tri, 3, "VEC3");
    accessors[0]["min"] = {0, 0, 0}, accessors[0]["max"] = {1, 1, 0};
    if (!t.empty()) attrs["TRANSLATION"] = add(t.data(), t.size() * 12, t.size(), "VEC3");
    if (!r.empty()) attrs["ROTATION"] = add(r.data(), r.size() * 16, r.size(), "VEC4");
    if (!s.empty()) attrs["SCALE"] = add(s.data(), s.size() * 12, s.size(), "VEC3");
    nlohmann::json j;
    j["asset"] = {{"version", "2.0"}};
    j["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    j["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
    j["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    j["bufferViews"] = views;
    j["accessors"] = accessors;
    j["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}};
    j["nodes"] = {{{"mesh", 0}, {"translation", {0, 0, 10}}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attrs}}}}}}};
    j["scenes"] = {{{"nodes", {0}}}};
    return j;
}
std::vector<glm::dvec3> worldCorners(const Scene& s) {
    std::vector<glm::dvec3> out;
    for (uint32_t i : s.indices)
        out.push_back(s.toWorld(s.vertices[i].position));
    return out;
}
} // namespace

TEST(Instancing, EveryInstanceIsDrawnWithItsTransformInTheNodesFrame) {
    const float h = 0.70710678f; // 90 degrees about +z: (x, y, z, w) = (0, 0, sin 45, cos 45)
    const nlohmann::json j = instanced({{0, 0, 0}, {5, 0, 0}, {0, 5, 0}}, {{0, 0, 0, 1}, {0, 0, h, h}, {0, 0, 0, 1}},
                                       {{1, 1, 1}, {1, 1, 1}, {2, 2, 2}});
    const Scene s = loadGltf(writeTemp("instanced.gltf", j.dump()));
    ASSERT_EQ(s.triangleCount(), 3u);
    const std::vector<glm::dvec3> c = worldCorners(s);
    auto near = [](glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-5; };
    // Instance 0: as is, at the node's z = 10.
    EXPECT_TRUE(near(c[1], {1, 0, 10})) << c[1].x << " " << c[1].y << " " << c[1].z;
    // Instance 1: rotated 90 degrees about z (x -> y), then moved by (5, 0, 0).
    bool rotated = false, scaled = false;
    for (const auto& p : c) {
        rotated = rotated || near(p, {5, 1, 10});
        scaled = scaled || near(p, {2, 5, 10}); // instance 2: (1,0,0) x 2 + (0, 5, 0)
    }
    EXPECT_TRUE(rotated);
    EXPECT_TRUE(scaled);
}

TEST(Instancing, TheBudgetCountsEveryInstanceBeforeAnyIsRead) {
    const SceneBudget saved = sceneBudget();
    SceneBudget b = saved;
    b.triangles = 100;
    setSceneBudget(b);
    const nlohmann::json j = instanced(std::vector<glm::vec3>(500, glm::vec3(0.0f)), {}, {});
    const std::string e = errorOf([&] { loadGltf(writeTemp("instanced_many.gltf", j.dump())); });
    setSceneBudget(saved);
    EXPECT_NE(e.find("expands to 500 triangles, past the budget of 100 triangles"), std::string::npos) << e;
}

TEST(Instancing, BrokenInstancesAndUnsupportedRequirementsAreRefusedByName) {
    nlohmann::json j = instanced({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0, 1}}, {});
    std::string e = errorOf([&] { loadGltf(writeTemp("instanced_counts.gltf", j.dump())); });
    EXPECT_NE(e.find("EXT_mesh_gpu_instancing attributes have different counts (2 and 1)"), std::string::npos) << e;
    j = instanced({{0, 0, 0}}, {}, {});
    j["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"] = 99;
    e = errorOf([&] { loadGltf(writeTemp("instanced_bad.gltf", j.dump())); });
    EXPECT_NE(e.find("attribute TRANSLATION is not an accessor of the file"), std::string::npos) << e;
    for (const char* ext : {"EXT_meshopt_compression", "KHR_mesh_quantization", "EXT_some_future_geometry"}) {
        j = instanced({{0, 0, 0}}, {}, {});
        j["extensionsRequired"].push_back(ext);
        e = errorOf([&] { loadGltf(writeTemp("instanced_req.gltf", j.dump())); });
        EXPECT_NE(e.find(std::string("requires unsupported extension ") + ext), std::string::npos) << e;
    }
    for (const char* ext : {"KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform"}) {
        j = instanced({{0, 0, 0}}, {}, {});
        j["extensionsRequired"].push_back(ext);
        EXPECT_EQ(errorOf([&] { loadGltf(writeTemp("instanced_ok.gltf", j.dump())); }), "") << ext;
    }
}
