// A generated glTF with a known answer for MASK cut-outs: a floor (y = 0, half-size `floorHalf`)
// under a thin square lid (y = `height`, half-size `lidHalf`) whose base-colour alpha is a
// checkerboard of `cells` x `cells` (cell (i, j) solid when i + j is even), cut at 0.5: half the
// lid's area open. The image is a PNG as a data URI, a file beside the scene or a bufferView.
#pragma once
#include "test_util.h"

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace ssaotest {

struct LidSpec {
    float floorHalf = 2.0f, lidHalf = 0.5f, height = 0.25f;
    int cells = 8, texelsPerCell = 4;
    enum class Image { DataUri, File, BufferView } image = Image::DataUri;
    std::string alphaMode = "MASK"; // "OPAQUE": the solid lid
    bool withLid = true;
    std::vector<unsigned char> png; // overrides the checkerboard (hostile images)
};

// RGBA PNG bytes of the checkerboard (alpha 255 solid, 0 open).
inline std::vector<unsigned char> checkerPng(int cells, int texelsPerCell) {
    const int n = cells * texelsPerCell;
    std::vector<unsigned char> px(size_t(n) * n * 4);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            unsigned char* p = &px[(size_t(y) * n + x) * 4];
            p[0] = p[1] = p[2] = 200;
            p[3] = ((x / texelsPerCell + y / texelsPerCell) % 2 == 0) ? 255 : 0;
        }
    std::vector<unsigned char> out;
    stbi_write_png_to_func([](void* ctx, void* data, int size) {
        auto* o = static_cast<std::vector<unsigned char>*>(ctx);
        o->insert(o->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
    }, &out, n, n, 4, px.data(), n * 4);
    return out;
}

// True when the lid is solid at (x, z) (inside it; the texel test of alpha_mask.h in closed form).
inline bool lidSolidAt(const LidSpec& s, double x, double z) {
    const double u = (x + s.lidHalf) / (2 * s.lidHalf), v = (z + s.lidHalf) / (2 * s.lidHalf);
    if (u < 0 || u >= 1 || v < 0 || v >= 1) return false;
    if (s.alphaMode != "MASK") return true;
    return (int(std::floor(u * s.cells)) + int(std::floor(v * s.cells))) % 2 == 0;
}

// Writes SSAOLAB_TEST_TMP/name.gltf (and name.png for Image::File); returns the .gltf's path.
inline std::string writeLidScene(const std::string& name, const LidSpec& s) {
    // Floor: 4 vertices, normal +y; lid: 4 vertices, normal -y (facing the floor), UV u along +x,
    // v along +z (the image's rows run along +z).
    const float F = s.floorHalf, L = s.lidHalf, h = s.height;
    const float pos[8][3] = {{-F, 0, -F}, {F, 0, -F}, {F, 0, F}, {-F, 0, F},
                             {-L, h, -L}, {L, h, -L}, {L, h, L}, {-L, h, L}};
    const float nrm[8][3] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -1, 0}, {0, -1, 0}};
    const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const uint16_t idx[6] = {0, 2, 1, 0, 3, 2};
    std::vector<unsigned char> bin(sizeof pos + sizeof nrm + sizeof uv + sizeof idx);
    size_t at = 0;
    for (auto [p, n] : {std::pair<const void*, size_t>{pos, sizeof pos}, {nrm, sizeof nrm}, {uv, sizeof uv}, {idx, sizeof idx}})
        std::memcpy(bin.data() + at, p, n), at += n;
    const std::vector<unsigned char> png = s.png.empty() ? checkerPng(s.cells, s.texelsPerCell) : s.png;
    const size_t pngAt = bin.size();
    if (s.image == LidSpec::Image::BufferView) bin.insert(bin.end(), png.begin(), png.end());
    nlohmann::json j;
    j["asset"] = {{"version", "2.0"}};
    j["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    j["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof pos}},
                        {{"buffer", 0}, {"byteOffset", sizeof pos}, {"byteLength", sizeof nrm}},
                        {{"buffer", 0}, {"byteOffset", sizeof pos + sizeof nrm}, {"byteLength", sizeof uv}},
                        {{"buffer", 0}, {"byteOffset", sizeof pos + sizeof nrm + sizeof uv}, {"byteLength", sizeof idx}},
                        {{"buffer", 0}, {"byteOffset", pngAt}, {"byteLength", png.size()}}};
    j["accessors"] = {
        {{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {-F, 0, -F}}, {"max", {F, 0, F}}},
        {{"bufferView", 0}, {"byteOffset", 48}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {-L, h, -L}}, {"max", {L, h, L}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"byteOffset", 48}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
    j["materials"] = {{{"name", "floor"}},
                      {{"name", "lid"}, {"alphaMode", s.alphaMode}, {"alphaCutoff", 0.5}, {"doubleSided", true},
                       {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    j["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}};
    j["textures"] = {{{"sampler", 0}, {"source", 0}}};
    if (s.image == LidSpec::Image::DataUri)
        j["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
    else if (s.image == LidSpec::Image::File) {
        writeTemp(name + ".png", std::string(png.begin(), png.end()));
        j["images"] = {{{"uri", name + ".png"}}};
    } else
        j["images"] = {{{"bufferView", 4}, {"mimeType", "image/png"}}};
    j["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 2}}}, {"indices", 5}, {"material", 0}}}}},
                   {{"primitives", {{{"attributes", {{"POSITION", 1}, {"NORMAL", 3}, {"TEXCOORD_0", 4}}}, {"indices", 5}, {"material", 1}}}}}};
    j["nodes"] = s.withLid ? nlohmann::json{{{"mesh", 0}}, {{"mesh", 1}}} : nlohmann::json{{{"mesh", 0}}};
    j["scenes"] = {{{"nodes", s.withLid ? nlohmann::json{0, 1} : nlohmann::json{0}}}};
    j["scene"] = 0;
    return writeTemp(name + ".gltf", j.dump());
}

// The reference's integral in closed form, evaluated finely: (1/pi) x the cosine-weighted measure
// of directions from (x, 0, z) (normal +y) that meet no solid lid point within R. Midpoint rule on
// the cosine-warped square (pdf cos/pi), n x n cells.
inline double lidAoNumeric(const LidSpec& s, double x, double z, double R, int n = 2000) {
    long open = 0;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const double u1 = (a + 0.5) / n, u2 = (b + 0.5) / n;
            const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
            const double dx = r * std::cos(phi), dz = r * std::sin(phi), dy = std::sqrt(1 - u1);
            const double t = s.height / dy; // to the lid's plane
            const bool blocked = s.withLid && t <= R && lidSolidAt(s, x + t * dx, z + t * dz);
            open += !blocked;
        }
    return double(open) / (double(n) * n);
}

} // namespace ssaotest
