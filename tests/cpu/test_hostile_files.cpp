// Hostile input, round two (issue 16): files, caches and command lines that crashed, hung, misled
// or overwrote. Each test is one example of a class, and failed before its fix.
#include "measure/sweep.h"
#include "scene/load/load_scene.h"
#include "gl/shader_library.h"
#include "scene/camera.h"
#include "scene/load/gltf_guard.h"
#include "scene/load/gltf_loader.h"
#include "settings/preset.h"
#include "util/error.h"
#include "util/json_file.h"

#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace ssao;
using ssaotest::errorOf;
using ssaotest::writeTemp;

namespace {

std::string tmp(const std::string& name) {
    fs::create_directories(SSAOLAB_TEST_TMP);
    return std::string(SSAOLAB_TEST_TMP) + "/" + name;
}

// One triangle, its buffer in an external .bin beside the file: a valid glTF to spoil.
nlohmann::json triangle(const std::string& binName) {
    std::vector<unsigned char> bytes(40, 0);
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    std::memcpy(bytes.data(), pos, 36);
    bytes[36] = 0, bytes[37] = 1, bytes[38] = 2;
    std::ofstream(tmp(binName), std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), 40);
    return nlohmann::json::parse(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
      "nodes":[{"mesh":0}],"meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
      "buffers":[{"byteLength":40,"uri":")" + binName + R"("}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":3}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,-1],"max":[1,0,0]},
                   {"bufferView":1,"componentType":5121,"count":3,"type":"SCALAR"}]})");
}

std::string save(const std::string& name, const nlohmann::json& j) {
    return writeTemp(name, j.dump());
}

std::string nested(size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

std::string loadError(const std::string& path) {
    return errorOf([&] { loadScene(path); });
}

} // namespace

TEST(HostileFiles, DeeplyNestedExtrasAndExtensionsAreRefusedBeforeParsing) {
    // 20 000 nested arrays in a node's extras crashed tinygltf's recursive conversion (SIGSEGV).
    nlohmann::json j = triangle("deep.bin");
    std::string text = j.dump();
    const std::string node = R"("nodes":[{"mesh":0)";
    text.replace(text.find(node), node.size(), node + R"(,"extras":)" + nested(20000));
    const std::string e1 = loadError(writeTemp("deep_extras.gltf", text));
    EXPECT_NE(e1.find("deeper than 64 levels"), std::string::npos) << e1;
    text = j.dump();
    const std::string mesh = R"({"name":"tri")";
    text.replace(text.find(mesh), mesh.size(), R"({"name":"tri","extensions":{"x":)" + nested(20000) + "}");
    const std::string e2 = loadError(writeTemp("deep_ext.gltf", text));
    EXPECT_NE(e2.find("deeper than 64 levels"), std::string::npos) << e2;
    EXPECT_EQ(jsonNestingDepth("[\"[[[[\", {\"a\": [1]}]", 20), 3u); // brackets in strings do not count
}

TEST(HostileFiles, IndicesBeyondThirtyTwoBitsAreRefusedNotWrapped) {
    // 4294967296 became 0 when tinygltf narrowed it to int: another object drew in its place.
    for (const char* where : {"bufferView", "mesh", "root", "buffer"})
        for (const char* value : {"4294967296", "-4294967296"}) {
            nlohmann::json j = triangle("wide.bin");
            const nlohmann::json v = nlohmann::json::parse(value);
            if (std::string(where) == "bufferView") j["accessors"][0]["bufferView"] = v;
            if (std::string(where) == "mesh") j["nodes"][0]["mesh"] = v;
            if (std::string(where) == "root") j["scenes"][0]["nodes"][0] = v;
            if (std::string(where) == "buffer") j["bufferViews"][0]["buffer"] = v;
            const std::string e = loadError(save("wide.gltf", j));
            EXPECT_NE(e.find("is not an index"), std::string::npos) << where << " " << value << ": " << e;
        }
    EXPECT_EQ(loadError(save("narrow.gltf", triangle("narrow.bin"))), ""); // the untouched file loads
}

TEST(HostileFiles, AGlbChunkRunningPastTheFileIsRefused) {
    // The BIN chunk's length 8 bytes past the end: tinygltf read past its heap buffer (valgrind)
    // and the bytes became a triangle, exit 0.
    const std::string json = R"({"asset":{"version":"2.0"}})";
    std::string jsonChunk = json;
    while (jsonChunk.size() % 4)
        jsonChunk.push_back(' ');
    auto le = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const std::string bin(16, '\0');
    std::string glb = "glTF" + le(2) + le(0) + le(uint32_t(jsonChunk.size())) + "JSON" + jsonChunk +
                      le(uint32_t(bin.size() + 8)) + std::string("BIN\0", 4) + bin;
    const uint32_t total = uint32_t(glb.size());
    glb.replace(8, 4, le(total));
    const std::string e = loadError(writeTemp("long_bin.glb", glb));
    EXPECT_NE(e.find("BIN chunk (24 bytes) runs 8 bytes past the end of the file"), std::string::npos) << e;
    glb.replace(8, 4, le(total + 4)); // and a header that lies about the length
    EXPECT_NE(loadError(writeTemp("long_header.glb", glb)).find("the GLB header says"), std::string::npos);
}

TEST(HostileFiles, AFileWithoutScenesDrawsEachTreeOnce) {
    // Before: every node was a root, so node 1 - node 0's child - was "listed elsewhere".
    nlohmann::json j = triangle("noscene.bin");
    j.erase("scenes");
    j.erase("scene");
    j["nodes"] = nlohmann::json::parse(R"([{"children":[1]},{"mesh":0}])");
    Scene s;
    ASSERT_EQ(errorOf([&] { s = loadScene(save("noscene.gltf", j)); }), "");
    EXPECT_EQ(s.triangleCount(), 1u);
}

TEST(HostileFiles, ImagesAreNeverRead) {
    // 64 images naming one sparse 2 GiB file took minutes and 2 GiB: tinygltf read each whole.
    const std::string big = tmp("sparse_2g.png");
    {
        std::ofstream(big, std::ios::binary) << "x";
        ASSERT_EQ(::truncate(big.c_str(), off_t(2) << 30), 0);
    }
    nlohmann::json j = triangle("images.bin");
    for (int i = 0; i < 64; ++i)
        j["images"].push_back({{"uri", "sparse_2g.png"}});
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_EQ(loadError(save("images.gltf", j)), "");
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(s, 5.0) << "reading 64 x 2 GiB takes minutes; not reading them takes milliseconds";
    fs::remove(big);
}

TEST(HostileFiles, AHugeMeshNameOnManyPrimitivesLoadsInLinearTime) {
    // An 8 MB name on 6 000 primitives: the name was copied into a label per primitive (> 20 s).
    nlohmann::json j = triangle("named.bin");
    j["meshes"][0]["name"] = std::string(8 << 20, 'n');
    const nlohmann::json prim = j["meshes"][0]["primitives"][0];
    for (int i = 0; i < 5999; ++i)
        j["meshes"][0]["primitives"].push_back(prim);
    const std::string path = save("named.gltf", j);
    const auto t0 = std::chrono::steady_clock::now();
    Scene s;
    ASSERT_EQ(errorOf([&] { s = loadScene(path); }), "");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(s.triangleCount(), 6000u);
    EXPECT_LT(seconds, 15.0) << "a label per primitive copies 48 GB";
}

TEST(HostileFiles, BuffersAndTheExpandedSceneAreBudgetedInBytesBeforeAllocating) {
    const SceneBudget saved = sceneBudget();
    // Two buffers naming one sparse file count twice (once took 4 GiB for 2 GiB of zeros).
    const std::string sparse = tmp("sparse_buffer.bin");
    {
        std::ofstream(sparse, std::ios::binary) << "x";
        ASSERT_EQ(::truncate(sparse.c_str(), off_t(40) << 20), 0); // 40 MiB of nothing
    }
    setSceneBudget({saved.triangles, size_t(64) << 20});
    nlohmann::json j = triangle("budget.bin");
    j["buffers"] = nlohmann::json::array({{{"byteLength", 40 << 20}, {"uri", "sparse_buffer.bin"}},
                                          {{"byteLength", 40 << 20}, {"uri", "sparse_buffer.bin"}}});
    j["bufferViews"][1]["buffer"] = 1;
    const std::string e1 = loadError(save("two_buffers.gltf", j));
    EXPECT_NE(e1.find("past the budget of 64 MiB"), std::string::npos) << e1;
    // A GLB larger than the budget is refused before it is read.
    const std::string glb = tmp("sparse.glb");
    {
        std::ofstream(glb, std::ios::binary) << "glTF";
        ASSERT_EQ(::truncate(glb.c_str(), off_t(80) << 20), 0);
    }
    EXPECT_NE(loadError(glb).find("larger than 64 MiB"), std::string::npos) << loadError(glb);
    // One accessor shared by many primitives: the expansion is counted from the accessors first.
    nlohmann::json k = triangle("expand.bin");
    k["accessors"][0]["count"] = 3;
    const nlohmann::json prim = k["meshes"][0]["primitives"][0];
    k["meshes"][0]["primitives"] = nlohmann::json::array();
    for (int i = 0; i < 900; ++i)
        k["meshes"][0]["primitives"].push_back(prim);
    setSceneBudget({saved.triangles, size_t(100) * 1024}); // 100 KiB: 900 flat triangles take ~130 KiB
    const std::string e3 = loadError(save("expand.gltf", k));
    EXPECT_NE(e3.find("MiB of vertices and indices, past the budget"), std::string::npos) << e3;
    setSceneBudget(saved);
    EXPECT_EQ(loadError(save("expand.gltf", k)), "");
    fs::remove(sparse);
    fs::remove(glb);
}

TEST(HostileFiles, ASceneOpenedThroughASymlinkFindsItsBuffers) {
    // The buffers were looked up beside the link while the folder check used the target's folder.
    const std::string dir = tmp("linked_scene");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string link = dir + "/cornell.gltf";
    ASSERT_EQ(::symlink((std::string(SSAOLAB_SCENES_DIR) + "/CornellBox/cornellBox.gltf").c_str(), link.c_str()), 0);
    Scene s;
    ASSERT_EQ(errorOf([&] { s = loadScene(link); }), "");
    EXPECT_EQ(s.triangleCount() + s.materials.blend, 16732u); // the glass sphere (BLEND) is skipped
}

TEST(HostileFiles, SweepsNestedDeepOrMultiplyingIntoDuplicatesAreRefused) {
    // 200 000 nested lists in `vary` crashed while the JSON was copied, before any validation.
    const std::string deep = writeTemp("deep_sweep.json", R"({"groups":[{"vary":{"ao.power":)" + nested(200000) + "}}]}");
    EXPECT_NE(errorOf([&] { loadSweep(deep); }).find("deeper than 64 levels"), std::string::npos);
    // Three 1000-value lists of one value: 10^9 combinations, every one a duplicate, ran for ever.
    nlohmann::json j;
    std::vector<double> ones(1000, 1.0);
    j["groups"] = {{{"vary", {{"ao.power", ones}, {"kernel.bias", std::vector<double>(1000, 0.05)},
                              {"denoise.sigma", std::vector<double>(1000, 2.0)}}}}};
    const std::string e = errorOf([&] { parseSweep(j, "sweep test"); });
    EXPECT_NE(e.find("1000000000 combinations, more than 2000"), std::string::npos) << e;
}

TEST(HostileFiles, APresetOrSweepThatIsAFifoIsRefusedNotWaitedOn) {
    // The glTF loader refused FIFOs; presets (by name or path) and --sweep files blocked for ever.
    const std::string fifo = tmp("fifo.json");
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(errorOf([&] { readPresetFile(fifo); }).find("not a regular file"), std::string::npos);
    EXPECT_NE(errorOf([&] { loadSweep(fifo); }).find("not a regular file"), std::string::npos);
    fs::remove(fifo);
}

TEST(HostileFiles, LongShaderLinesAndIncludeNamesAreTextNotRecursion) {
    // A line of 60 000 spaces (or a 100 000-character #include name) crashed std::regex.
    const std::string dir = tmp("shader_text");
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir + "/spaces.frag") << "#version 450 core\n" << std::string(60000, ' ') << "\nvoid main() {}\n";
    std::ofstream(dir + "/longinc.frag") << "#version 450 core\n#include \"" << std::string(100000, 'a') << "\"\n";
    std::vector<std::string> files;
    EXPECT_EQ(errorOf([&] { gl::preprocessShader(dir, "spaces.frag", {}, files); }), "");
    EXPECT_NE(errorOf([&] { gl::preprocessShader(dir, "longinc.frag", {}, files); }).find("longer than 256"),
              std::string::npos);
    const std::string mapped = gl::mapLogToFiles(std::string(60000, ' ') + "0:3(1): error", {"a.frag"});
    EXPECT_NE(mapped.find(std::string(60000, ' ') + "shaders/a.frag:3: error"), std::string::npos);
}

TEST(HostileFiles, AReversedNearPlaneBelowFloatsNormalRangeIsRefusedByName) {
    // near 1e-38 with reversed-Z, said to handle any ratio, drew nothing ("no geometry in view").
    Camera c;
    c.depth = DepthMode::Reversed;
    c.nearZ = 1e-38f;
    EXPECT_NE(errorOf([&] { validateCamera(c); }).find("reversed-Z stores depth as near/z"), std::string::npos);
    c.nearZ = 1e-30f;
    EXPECT_EQ(errorOf([&] { validateCamera(c); }), "");
}
