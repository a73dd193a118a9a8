// Untrusted input, budgeted before anything is allocated or looped over: images (a JPEG's scans, a
// PNG's inflated rows, every header's pixels), GPU instances, the screen-space oracle's G-buffer;
// and user folders from the environment, where an empty variable means unset.
#include "base/image.h"
#include "lid_scene.h"
#include "reference/screen_layers.h"
#include "scene/closed_shells.h"
#include "scene/load/gltf_loader.h"
#include "scene/scene.h"
#include "settings/preset_store.h"
#include "test_util.h"
#include "util/image_budget.h"

#include <gtest/gtest.h>

#include <tuple>

#include <set>

#include <cstdlib>
#include <cstring>
#include <filesystem>

using namespace ssao;
using namespace ssaotest;

namespace {

struct BudgetScope {
    SceneBudget saved = sceneBudget();
    ~BudgetScope() { setSceneBudget(saved); }
};

// A grayscale progressive JPEG (SOF2) of w x h pixels made of `scans` DC-first scans, each one byte
// of entropy-coded data (a decoder reads zeros past it: every block's DC difference is 0).
std::vector<unsigned char> progressiveJpeg(int w, int h, int scans) {
    std::vector<unsigned char> j = {0xFF, 0xD8};
    auto segment = [&](unsigned char marker, std::vector<unsigned char> body) {
        const size_t len = body.size() + 2;
        j.insert(j.end(), {0xFF, marker, static_cast<unsigned char>(len >> 8), static_cast<unsigned char>(len & 255)});
        j.insert(j.end(), body.begin(), body.end());
    };
    std::vector<unsigned char> dqt(65, 1);
    dqt[0] = 0x00; // 8-bit table 0
    segment(0xDB, dqt);
    auto hi = [](int v) { return static_cast<unsigned char>(v >> 8); };
    auto lo = [](int v) { return static_cast<unsigned char>(v & 255); };
    segment(0xC2, {8, hi(h), lo(h), hi(w), lo(w), 1, 1, 0x11, 0});
    std::vector<unsigned char> dht(18, 0); // DC table 0: one 1-bit code, for category 0
    dht[1] = 1;
    segment(0xC4, dht);
    for (int s = 0; s < scans; ++s) {
        segment(0xDA, {1, 1, 0x00, 0, 0, 0x00});
        j.push_back(0x00);
    }
    j.insert(j.end(), {0xFF, 0xD9});
    return j;
}

void put32be(std::vector<unsigned char>& v, uint32_t x) {
    for (int k = 3; k >= 0; --k)
        v.push_back(static_cast<unsigned char>(x >> (8 * k)));
}

// An 8-bit grayscale PNG whose header says w x h and whose IDAT inflates to `rawBytes` zero bytes
// (stored deflate blocks; the chunks' CRCs are left 0: stb does not check them).
std::vector<unsigned char> grayPng(uint32_t w, uint32_t h, size_t rawBytes) {
    std::vector<unsigned char> z = {0x78, 0x01};
    size_t left = rawBytes;
    do {
        const size_t n = std::min<size_t>(left, 65535);
        left -= n;
        z.push_back(left == 0 ? 1 : 0);
        z.insert(z.end(), {static_cast<unsigned char>(n & 255), static_cast<unsigned char>(n >> 8),
                           static_cast<unsigned char>(~n & 255), static_cast<unsigned char>((~n >> 8) & 255)});
        z.insert(z.end(), n, 0);
    } while (left > 0);
    put32be(z, uint32_t(rawBytes % 65521) << 16 | 1); // Adler-32 of zeros: a = 1, b = n
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    auto chunk = [&](const char* type, const std::vector<unsigned char>& data) {
        put32be(png, uint32_t(data.size()));
        png.insert(png.end(), type, type + 4);
        png.insert(png.end(), data.begin(), data.end());
        put32be(png, 0);
    };
    std::vector<unsigned char> ihdr;
    put32be(ihdr, w), put32be(ihdr, h);
    ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});
    chunk("IHDR", ihdr);
    chunk("IDAT", z);
    chunk("IEND", {});
    return png;
}

std::string maskSceneError(const std::string& name, const std::vector<unsigned char>& image) {
    LidSpec spec;
    spec.png = image;
    return errorOf([&] { loadGltf(writeLidScene(name, spec)); });
}

// One triangle on node 0 drawn once per TRANSLATION (float VEC3) of EXT_mesh_gpu_instancing;
// `mode` 0 (POINTS) draws no triangle at all.
nlohmann::json instancedTriangle(size_t instances, int mode = 4) {
    std::vector<unsigned char> bin(36 + 12 * instances, 0);
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::memcpy(bin.data(), tri, sizeof tri);
    for (size_t i = 0; i < instances; ++i) {
        const float t[3] = {float(i % 100) * 2.0f, float(i / 100) * 2.0f, 0.0f};
        std::memcpy(bin.data() + 36 + 12 * i, t, sizeof t);
    }
    nlohmann::json j;
    j["asset"] = {{"version", "2.0"}};
    j["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    j["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    j["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 12 * instances}}};
    j["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                       {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                      {{"bufferView", 1}, {"componentType", 5126}, {"count", instances}, {"type", "VEC3"}}};
    j["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", mode}}}}}};
    j["nodes"] = {{{"mesh", 0}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", 1}}}}}}}}};
    j["scenes"] = {{{"nodes", {0}}}};
    return j;
}

} // namespace

TEST(Budgets, AJpegOfThousandsOfScansIsRefusedBeforeItIsDecoded) {
    // Before: stb decoded every scan over the whole image (a MASK texture of 5000 scans ran past 20 s).
    const std::string e = maskSceneError("lid_scans", progressiveJpeg(1024, 1024, 2000));
    EXPECT_NE(e.find("2000 scans, past the limit of 500"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    // An ordinary progressive JPEG (ten scans) still decodes.
    EXPECT_EQ(maskSceneError("lid_scans_ok", progressiveJpeg(64, 64, 10)), "");
}

TEST(Budgets, APngWhoseDataInflatesPastItsHeaderIsRefused) {
    // Before: stb inflated whatever the IDAT held (a 1x1 header over 3 GiB of zeros took 3 GiB).
    const std::string e = maskSceneError("lid_inflate", grayPng(1, 1, size_t(4) << 20));
    EXPECT_NE(e.find("inflates to more than the 1x1 pixels its header states"), std::string::npos) << e;
    EXPECT_EQ(maskSceneError("lid_inflate_ok", grayPng(4, 2, 2 * 5)), ""); // a row: filter byte + 4 pixels
}

TEST(Budgets, ImagesAreReadThroughTheFileGateAndTheirHeaderBudget) {
    // Before: readPng handed the path to stb, which took a 30000 x 30000 header at its word.
    const std::string bomb = writeTemp("bomb.png", [] {
        const std::vector<unsigned char> p = grayPng(30000, 30000, 16);
        return std::string(p.begin(), p.end());
    }());
    std::string e = errorOf([&] { readPng(bomb); });
    EXPECT_NE(e.find("is 30000x30000 pixels: past the budget of 64 M pixels"), std::string::npos) << e;
    std::filesystem::create_directories(std::string(SSAOLAB_TEST_TMP) + "/a_folder.png");
    e = errorOf([&] { readPng(std::string(SSAOLAB_TEST_TMP) + "/a_folder.png"); });
    EXPECT_NE(e.find("is a folder, not a regular file"), std::string::npos) << e;
}

TEST(Budgets, AnInstancingAccessorIndexPastThirtyTwoBitsIsRefused) {
    // Before: 4294967296 became accessor 0 when tinygltf narrowed it to int.
    for (const char* value : {"4294967296", "-4294967296", "2147483648"}) {
        nlohmann::json j = instancedTriangle(2);
        j["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"] = nlohmann::json::parse(value);
        const std::string e = errorOf([&] { loadGltf(writeTemp("instanced_wide.gltf", j.dump())); });
        EXPECT_NE(e.find("TRANSLATION = " + std::string(value) + " is not an index"), std::string::npos) << e;
    }
}

TEST(Budgets, GpuInstancesPastTheTriangleBudgetAreRefusedByName) {
    // Before: instances of a mesh with no triangles passed the triangle budget and were each walked.
    BudgetScope scope;
    SceneBudget b = sceneBudget();
    b.triangles = 1000;
    setSceneBudget(b);
    const std::string e = errorOf([&] { loadGltf(writeTemp("instanced_points.gltf", instancedTriangle(5000, 0).dump())); });
    EXPECT_NE(e.find("5000 instances, past the budget of 1000 triangles"), std::string::npos) << e;
    EXPECT_NE(e.find("--max-triangles"), std::string::npos) << e;
}

TEST(Budgets, TheInstancesOfOnePrimitiveAreOneDraw) {
    // Before: one draw per instance (999 000 one-triangle instances: 999 000 draw calls a frame).
    const Scene s = loadGltf(writeTemp("instanced_draws.gltf", instancedTriangle(300).dump()));
    EXPECT_EQ(s.triangleCount(), 300u);
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].indexCount, 900u);
}

TEST(Budgets, AnOracleGBufferPastItsBudgetIsRefusedBeforeItIsAllocated) {
    // Before: a 4096-pixel guard band and two layers around a 64 x 36 frame allocated 3.6 GiB.
    Camera cam;
    const std::string e = errorOf([&] { ScreenLayers(cam, 64, 36, 2, 1.0f, 4096); });
    EXPECT_NE(e.find("screen oracle: its G-buffer would take 3.54 GiB"), std::string::npos) << e;
    EXPECT_NE(e.find("past the budget of 1 GiB"), std::string::npos) << e;
    EXPECT_NE(e.find("--oracle-guard"), std::string::npos) << e;
    EXPECT_EQ(errorOf([&] { ScreenLayers(cam, 64, 36, 2, 1.0f, 64); }), "");
}

TEST(Budgets, AnEmptyXdgConfigHomeMeansUnset) {
    // XDG Base Directory: empty means unset. Before: XDG_CONFIG_HOME="" put presets at /ssaolab/presets.
    const char* keepDir = std::getenv("SSAOLAB_PRESET_DIR");
    const char* keepXdg = std::getenv("XDG_CONFIG_HOME");
    const char* keepHome = std::getenv("HOME");
    const std::string dir = keepDir ? keepDir : "", xdg = keepXdg ? keepXdg : "", home = keepHome ? keepHome : "";
    ::unsetenv("SSAOLAB_PRESET_DIR");
    ::setenv("XDG_CONFIG_HOME", "", 1);
    ::setenv("HOME", "/home/someone", 1);
    EXPECT_EQ(PresetStore::defaultUserDir(), "/home/someone/.config/ssaolab/presets");
    ::setenv("SSAOLAB_PRESET_DIR", "", 1);
    EXPECT_EQ(PresetStore::defaultUserDir(), "/home/someone/.config/ssaolab/presets");
    ::setenv("XDG_CONFIG_HOME", "/xdg", 1);
    EXPECT_EQ(PresetStore::defaultUserDir(), "/xdg/ssaolab/presets");
    auto restore = [](const char* name, const char* was, const std::string& value) {
        if (was) ::setenv(name, value.c_str(), 1);
        else ::unsetenv(name);
    };
    restore("SSAOLAB_PRESET_DIR", keepDir, dir), restore("XDG_CONFIG_HOME", keepXdg, xdg), restore("HOME", keepHome, home);
}

TEST(Budgets, TextureCoordinateSetsPastThirtyTwoBitsAreRefused) {
    // Before: texCoord 4294967296 became TEXCOORD_0 when tinygltf narrowed it to int.
    const std::string path = writeLidScene("lid_texcoord", LidSpec{});
    for (const bool viaTransform : {false, true}) {
        nlohmann::json j = nlohmann::json::parse(slurp(path));
        nlohmann::json& info = j["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"];
        if (viaTransform) info["extensions"]["KHR_texture_transform"]["texCoord"] = 4294967296LL;
        else info["texCoord"] = 4294967296LL;
        const std::string e = errorOf([&] { loadGltf(writeTemp("lid_texcoord_wide.gltf", j.dump())); });
        EXPECT_NE(e.find("texCoord = 4294967296 is not an index"), std::string::npos) << viaTransform << ": " << e;
    }
}

TEST(Budgets, TheImageHeaderIsReadWithoutDecoding) {
    const std::vector<unsigned char> jpeg = progressiveJpeg(640, 48, kMaxJpegScans);
    ImageHeader h = readImageHeader(jpeg.data(), jpeg.size());
    EXPECT_EQ(h.format, ImageFormat::Jpeg);
    EXPECT_EQ(h.width, 640u);
    EXPECT_EQ(h.height, 48u);
    EXPECT_EQ(h.scans, kMaxJpegScans);
    EXPECT_NO_THROW(checkImageBudget(jpeg.data(), jpeg.size(), ImageBudget{}, "at the limit"));
    const std::vector<unsigned char> over = progressiveJpeg(640, 48, kMaxJpegScans + 1);
    EXPECT_NE(errorOf([&] { checkImageBudget(over.data(), over.size(), ImageBudget{}, "x"); }).find("501 scans"),
              std::string::npos);
    const std::vector<unsigned char> png = grayPng(300, 200, 200 * 301);
    h = checkImageBudget(png.data(), png.size(), ImageBudget{}, "png");
    EXPECT_EQ(h.format, ImageFormat::Png);
    EXPECT_EQ(h.pixels(), 60000u);
    const std::string exrPath = std::string(SSAOLAB_TEST_TMP) + "/header.exr";
    writeExr(Image{40, 30, 1, std::vector<float>(1200, 0.25f)}, exrPath);
    const std::string exr = slurp(exrPath);
    h = readImageHeader(reinterpret_cast<const unsigned char*>(exr.data()), exr.size());
    EXPECT_EQ(h.format, ImageFormat::Exr);
    EXPECT_EQ(h.width, 40u);
    EXPECT_EQ(h.height, 30u);
    // The budget counts what was decoded before, names its option, and an EXR beyond it is never read.
    ImageBudget b{1200, 100, "MASK textures", "--max-mask-mpix"};
    const std::string e = errorOf([&] { readExr(exrPath, b); });
    EXPECT_NE(e.find("is 40x30 pixels: past the budget of 0 M pixels for MASK textures (0 M already decoded) (raise it "
                     "with ssaolab --max-mask-mpix N)"),
              std::string::npos)
        << e;
    b.used = 0;
    const Image back = readExr(exrPath, b);
    EXPECT_EQ(back.width, 40);
    EXPECT_EQ(back.at(3, 3), 0.25f);
    EXPECT_NE(errorOf([&] { readPng(exrPath); }).find("an OpenEXR file"), std::string::npos);
}

TEST(Budgets, TheOracleEstimateIsAPureFunctionOfItsDimensions) {
    const uint64_t one = ScreenLayers::bytes(1, 1, 1, 0);
    EXPECT_GE(one, 28u); // a point, a normal and two flags
    EXPECT_EQ(ScreenLayers::bytes(64, 36, 1, 0), 64u * 36u * one);
    EXPECT_EQ(ScreenLayers::bytes(64, 36, 2, 4096), 2u * 8256u * 8228u * one);
    // A 4K frame with two layers fits; a 64 x 36 frame with a 4096-pixel band does not.
    EXPECT_NO_THROW(ScreenLayers::checkBudget(3840, 2160, 2, 256));
    EXPECT_LE(ScreenLayers::bytes(3840, 2160, 2, 256), kScreenLayersBudget);
    EXPECT_THROW(ScreenLayers::checkBudget(64, 36, 2, 4096), Error);
}

TEST(Budgets, AGridOfInstancesSpreadsOverTheWeldTable) {
    // One draw for 300 000 instances: the closed-shell analysis welds their 900 000 corners in an
    // open-addressing table. A plain product of round coordinates' bits piled them into a handful
    // of slots (999 000 instances: 24 s in classifyShells); every distinct corner must find a
    // slot of its own nearly always.
    const Scene s = loadGltf(writeTemp("instanced_grid.gltf", instancedTriangle(300000).dump()));
    ASSERT_EQ(s.draws.size(), 1u);
    std::set<std::tuple<float, float, float>> corners;
    for (const Vertex& v : s.vertices)
        corners.insert({v.position.x, v.position.y, v.position.z});
    size_t tableSize = 16;
    while (tableSize < 2 * s.vertices.size()) tableSize *= 2;
    std::set<uint64_t> slots;
    for (const auto& [x, y, z] : corners)
        slots.insert(weldHash(glm::vec3(x, y, z)) & (tableSize - 1));
    std::printf("%zu distinct corners in %zu slots of %zu\n", corners.size(), slots.size(), tableSize);
    EXPECT_GT(double(slots.size()), 0.75 * double(corners.size()));
    EXPECT_EQ(classifyShells(s.vertices, s.indices, 0, s.triangleCount()).size(), 300000u);
}
