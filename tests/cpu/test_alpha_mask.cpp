// MASK cut-outs (glTF alphaMode MASK, scene/alpha_mask.h): the reference sees through the holes
// of a checkerboard lid as a fine numeric integral says, only MASK textures are decoded, within a
// budget checked from the header, and hostile images are one clear error each.
#include "lid_scene.h"
#include "reference/embree_scene.h"
#include "reference/reference_ao.h"
#include "scene/alpha_mask.h"
#include "scene/load/gltf_loader.h"
#include "scene/load/mask_textures.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace ssao;
using namespace ssaotest;

namespace {
// A camera between floor and lid, looking straight down at the floor point under the lid's centre:
// the lid cannot hide it, and every pixel sees a point within a few thousandths of the centre.
Camera underTheLid(const LidSpec& s) {
    Camera c;
    c.eye = {0, s.height * 0.5f, 0};
    c.target = {0, 0, 0};
    c.up = {0, 0, -1};
    c.fovYDeg = 2.0f;
    c.nearZ = 0.001f;
    c.farZ = 1.0f;
    return c;
}
double referenceUnderTheLid(const LidSpec& spec, const std::string& name, float R) {
    const Scene s = loadGltf(writeLidScene(name, spec));
    EmbreeScene rt(s);
    const ReferenceImage img = traceReference(rt, underTheLid(spec), 4, 4, {R, 8192});
    double sum = 0;
    for (float a : img.ao)
        sum += a;
    return sum / double(img.ao.size());
}
struct BudgetScope {
    SceneBudget saved = sceneBudget();
    ~BudgetScope() { setSceneBudget(saved); }
};
} // namespace

TEST(AlphaMask, TheCheckerboardLidOpensHalfItsCellsToTheReference) {
    const float R = 1.0f;
    LidSpec mask, solid, none;
    solid.alphaMode = "OPAQUE";
    none.withLid = false;
    const double refMask = referenceUnderTheLid(mask, "lid_mask", R);
    const double refSolid = referenceUnderTheLid(solid, "lid_solid", R);
    const double refNone = referenceUnderTheLid(none, "lid_none", R);
    const double numMask = lidAoNumeric(mask, 0, 0, R), numSolid = lidAoNumeric(solid, 0, 0, R);
    std::printf("lid under its centre (h = %.2f, half-size %.2f, R = %.1f, %dx%d cells): reference solid %.4f, "
                "checkerboard %.4f, no lid %.4f; numeric integral solid %.4f, checkerboard %.4f\n",
                mask.height, mask.lidHalf, R, mask.cells, mask.cells, refSolid, refMask, refNone, numSolid, numMask);
    EXPECT_EQ(refNone, 1.0);
    EXPECT_NEAR(refSolid, numSolid, 0.02);
    EXPECT_NEAR(refMask, numMask, 0.02);
    EXPECT_GT(refMask, refSolid + 0.1) << "the holes let light in";
    EXPECT_LT(refMask, refNone - 0.1) << "the solid cells still occlude";
}

TEST(AlphaMask, EveryImageSourceGivesTheSameCutOut) {
    for (auto mode : {LidSpec::Image::DataUri, LidSpec::Image::File, LidSpec::Image::BufferView}) {
        LidSpec spec;
        spec.image = mode;
        const Scene s = loadGltf(writeLidScene("lid_source_" + std::to_string(int(mode)), spec));
        ASSERT_EQ(s.alphaTextures.size(), 1u);
        EXPECT_EQ(s.materials.mask, 2u);
        EXPECT_EQ(s.materials.opaque, 2u);
        EXPECT_EQ(s.materials.maskTextures, 1u);
        EXPECT_EQ(s.materials.maskPixels, 32u * 32u);
        EXPECT_EQ(s.uvs.size(), s.vertices.size());
        const Draw* lid = nullptr;
        for (const Draw& d : s.draws)
            if (d.mask) lid = &d;
        ASSERT_NE(lid, nullptr);
        // The test of alpha_mask.h at every cell centre against the closed form.
        for (int i = 0; i < spec.cells; ++i)
            for (int j = 0; j < spec.cells; ++j) {
                const glm::vec2 uv((i + 0.5f) / spec.cells, (j + 0.5f) / spec.cells);
                const double x = uv.x * 2 * spec.lidHalf - spec.lidHalf, z = uv.y * 2 * spec.lidHalf - spec.lidHalf;
                EXPECT_EQ(!cutOut(s, *lid, uv), lidSolidAt(spec, x, z)) << i << "," << j;
            }
    }
}

TEST(AlphaMask, WrapModesFollowGl) {
    EXPECT_EQ(wrapTexel(-0.01f, 4, Wrap::Repeat), 3);
    EXPECT_EQ(wrapTexel(1.01f, 4, Wrap::Repeat), 0);
    EXPECT_EQ(wrapTexel(-0.01f, 4, Wrap::Clamp), 0);
    EXPECT_EQ(wrapTexel(7.0f, 4, Wrap::Clamp), 3);
    EXPECT_EQ(wrapTexel(1.1f, 4, Wrap::Mirror), 3);  // texel 4 mirrors to 3
    EXPECT_EQ(wrapTexel(-0.1f, 4, Wrap::Mirror), 0); // texel -1 mirrors to 0
    EXPECT_EQ(wrapTexel(1e30f, 4, Wrap::Repeat), 0);
}

TEST(AlphaMask, ATextureBeyondTheBudgetIsRefusedFromItsHeader) {
    BudgetScope scope;
    SceneBudget b = sceneBudget();
    b.maskPixels = 512; // the lid's 32 x 32 texture is 1024
    setSceneBudget(b);
    const std::string e = errorOf([&] { loadGltf(writeLidScene("lid_budget", LidSpec{})); });
    EXPECT_NE(e.find("image 0 (the base-colour texture of material 'lid') is 32x32 pixels: past the budget of 0 M pixels"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("--max-mask-mpix"), std::string::npos) << e;
}

TEST(AlphaMask, HostileImagesAreOneClearErrorEach) {
    const std::vector<unsigned char> good = checkerPng(8, 4);
    // A PNG header claiming 23000 x 23000 (2 GB of RGBA) and nothing else: a decompression bomb is
    // refused before a byte is decoded.
    std::vector<unsigned char> bomb(good.begin(), good.begin() + 33);
    auto be32 = [&](size_t at, uint32_t v) {
        for (int k = 0; k < 4; ++k)
            bomb[at + size_t(k)] = static_cast<unsigned char>(v >> (24 - 8 * k));
    };
    be32(16, 23000), be32(20, 23000);
    const std::vector<unsigned char> truncated(good.begin(), good.begin() + long(good.size() / 2));
    const std::vector<unsigned char> notAnImage = {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'};
    struct Case {
        const char* name;
        std::vector<unsigned char> png;
        const char* expected;
    } cases[] = {{"bomb", bomb, "is 23000x23000 pixels: past the budget of 64 M pixels for MASK textures"},
                 {"truncated", truncated, "cannot be decoded"},
                 {"garbage", notAnImage, "is not a PNG or JPEG that can be read"}};
    for (const Case& c : cases) {
        LidSpec spec;
        spec.png = c.png;
        const std::string e = errorOf([&] { loadGltf(writeLidScene(std::string("lid_") + c.name, spec)); });
        EXPECT_NE(e.find(c.expected), std::string::npos) << c.name << ": " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
    }
    // A bufferView beyond its buffer, one that does not exist, a file outside the scene's folder.
    const std::string path = writeLidScene("lid_views", [] {
        LidSpec s;
        s.image = LidSpec::Image::BufferView;
        return s;
    }());
    auto withImage = [&](const std::string& name, const nlohmann::json& image, const nlohmann::json* view = nullptr) {
        nlohmann::json j = nlohmann::json::parse(slurp(path));
        j["images"][0] = image;
        if (view) j["bufferViews"][4] = *view;
        return errorOf([&] { loadGltf(writeTemp(name, j.dump())); });
    };
    const nlohmann::json far = {{"buffer", 0}, {"byteOffset", 100}, {"byteLength", 1 << 30}};
    EXPECT_NE(withImage("lid_far.gltf", {{"bufferView", 4}}, &far).find("its bufferView 4 lies outside its buffer"), std::string::npos)
        << withImage("lid_far.gltf", {{"bufferView", 4}}, &far);
    EXPECT_NE(withImage("lid_noview.gltf", {{"bufferView", 77}}).find("bufferView 77 does not exist"), std::string::npos);
    EXPECT_NE(withImage("lid_outside.gltf", {{"uri", "../../../../etc/passwd"}}).find("is outside the scene's folder"),
              std::string::npos)
        << withImage("lid_outside.gltf", {{"uri", "../../../../etc/passwd"}});
    EXPECT_NE(withImage("lid_missing.gltf", {{"uri", "nowhere.png"}}).find("nowhere.png"), std::string::npos);
}

TEST(AlphaMask, OnlyMaskTexturesAreDecodedAndAMaskWithoutTextureIsAllOrNothing) {
    LidSpec spec;
    spec.alphaMode = "OPAQUE"; // the same file with an opaque lid: its (bomb) image is never decoded
    std::vector<unsigned char> bomb = checkerPng(8, 4);
    bomb.resize(33);
    spec.png = bomb;
    Scene s;
    EXPECT_EQ(errorOf([&] { s = loadGltf(writeLidScene("lid_opaque_bomb", spec)); }), "");
    EXPECT_EQ(s.materials.maskTextures, 0u);
    EXPECT_TRUE(s.uvs.empty());
    // MASK with the factor alone: alpha 0.3 < cutoff 0.5 cuts the whole lid, 0.7 keeps it whole.
    const std::string path = writeLidScene("lid_factor", LidSpec{});
    for (double a : {0.3, 0.7}) {
        nlohmann::json j = nlohmann::json::parse(slurp(path));
        j["materials"][1]["pbrMetallicRoughness"] = {{"baseColorFactor", {1, 1, 1, a}}};
        const Scene f = loadGltf(writeTemp("lid_factor_" + std::to_string(int(a * 10)) + ".gltf", j.dump()));
        EXPECT_EQ(f.materials.mask, 2u);
        EXPECT_EQ(f.triangleCount(), a < 0.5 ? 2u : 4u) << a;
        EXPECT_EQ(f.materials.maskTextures, 0u);
    }
}
