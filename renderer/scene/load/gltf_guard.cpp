#include "scene/load/gltf_guard.h"

#include "util/error.h"
#include "util/file_kind.h"
#include "util/json_file.h"

#include <cstdint>
#include <cstring>
#include <limits>

namespace fs = std::filesystem;

namespace ssao {

namespace {

uint32_t le32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
void put32(std::vector<unsigned char>& v, uint32_t x) {
    for (int k = 0; k < 4; ++k)
        v.push_back(static_cast<unsigned char>(x >> (8 * k)));
}

constexpr uint32_t kGlbMagic = 0x46546C67; // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;

// One index: absent, or an integer in [0, 2^31).
void checkIndex(const nlohmann::json& parent, const char* key, const std::string& where) {
    if (!parent.is_object() || !parent.contains(key)) return;
    const nlohmann::json& v = parent[key];
    const std::string at = where + "." + key;
    if (!v.is_number_integer())
        throw Error(at + " must be an integer index");
    if (v.is_number_unsigned() ? v.get<uint64_t>() > uint64_t(std::numeric_limits<int32_t>::max())
                               : (v.get<int64_t>() < 0 || v.get<int64_t>() > std::numeric_limits<int32_t>::max()))
        throw Error(at + " = " + v.dump() + " is not an index (0 .. 2^31-1)");
}
void checkIndexArray(const nlohmann::json& parent, const char* key, const std::string& where) {
    if (!parent.is_object() || !parent.contains(key)) return;
    const nlohmann::json& a = parent[key];
    if (!a.is_array()) throw Error(where + "." + key + " must be an array of indices");
    for (size_t i = 0; i < a.size(); ++i) {
        const nlohmann::json holder = {{std::to_string(i), a[i]}};
        checkIndex(holder, std::to_string(i).c_str(), where + "." + key);
    }
}
void checkIndexMap(const nlohmann::json& m, const std::string& where) {
    if (!m.is_object()) return;
    for (auto& [k, v] : m.items())
        checkIndex(m, k.c_str(), where);
}
template <class F> void eachOf(const nlohmann::json& j, const char* key, const F& f) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_array()) return;
    const nlohmann::json& a = j[key];
    for (size_t i = 0; i < a.size(); ++i)
        f(a[i], std::string(key) + "[" + std::to_string(i) + "]");
}

// Every index field of glTF 2.0, checked in 64 bits before tinygltf narrows it to int.
void checkIndices(const nlohmann::json& j, const std::string& what) {
    checkIndex(j, "scene", what);
    eachOf(j, "scenes", [&](const nlohmann::json& s, const std::string& w) { checkIndexArray(s, "nodes", what + ": " + w); });
    eachOf(j, "nodes", [&](const nlohmann::json& n, const std::string& w) {
        for (const char* k : {"camera", "skin", "mesh"})
            checkIndex(n, k, what + ": " + w);
        checkIndexArray(n, "children", what + ": " + w);
        // Extensions ssaolab reads hold indices too: EXT_mesh_gpu_instancing's attribute accessors.
        if (n.is_object() && n.contains("extensions") && n["extensions"].is_object() &&
            n["extensions"].contains("EXT_mesh_gpu_instancing") && n["extensions"]["EXT_mesh_gpu_instancing"].is_object() &&
            n["extensions"]["EXT_mesh_gpu_instancing"].contains("attributes"))
            checkIndexMap(n["extensions"]["EXT_mesh_gpu_instancing"]["attributes"],
                          what + ": " + w + ".extensions.EXT_mesh_gpu_instancing.attributes");
    });
    eachOf(j, "meshes", [&](const nlohmann::json& m, const std::string& w) {
        eachOf(m, "primitives", [&](const nlohmann::json& p, const std::string& pw) {
            const std::string at = what + ": " + w + "." + pw;
            checkIndex(p, "indices", at);
            checkIndex(p, "material", at);
            if (p.is_object() && p.contains("attributes")) checkIndexMap(p["attributes"], at + ".attributes");
            eachOf(p, "targets", [&](const nlohmann::json& t, const std::string& tw) { checkIndexMap(t, at + "." + tw); });
        });
    });
    eachOf(j, "accessors", [&](const nlohmann::json& a, const std::string& w) {
        checkIndex(a, "bufferView", what + ": " + w);
        if (a.is_object() && a.contains("sparse") && a["sparse"].is_object())
            for (const char* part : {"indices", "values"})
                if (a["sparse"].contains(part)) checkIndex(a["sparse"][part], "bufferView", what + ": " + w + ".sparse." + part);
    });
    eachOf(j, "bufferViews", [&](const nlohmann::json& b, const std::string& w) { checkIndex(b, "buffer", what + ": " + w); });
    eachOf(j, "images", [&](const nlohmann::json& i, const std::string& w) { checkIndex(i, "bufferView", what + ": " + w); });
    eachOf(j, "textures", [&](const nlohmann::json& t, const std::string& w) {
        checkIndex(t, "sampler", what + ": " + w);
        checkIndex(t, "source", what + ": " + w);
    });
    // A texture reference: its texture, its UV set, and KHR_texture_transform's UV set (read too).
    auto textureInfo = [&](const nlohmann::json& t, const std::string& at) {
        checkIndex(t, "index", at);
        checkIndex(t, "texCoord", at);
        if (t.is_object() && t.contains("extensions") && t["extensions"].is_object() &&
            t["extensions"].contains("KHR_texture_transform"))
            checkIndex(t["extensions"]["KHR_texture_transform"], "texCoord", at + ".extensions.KHR_texture_transform");
    };
    eachOf(j, "materials", [&](const nlohmann::json& m, const std::string& w) {
        for (const char* tex : {"normalTexture", "occlusionTexture", "emissiveTexture"})
            if (m.is_object() && m.contains(tex)) textureInfo(m[tex], what + ": " + w + "." + tex);
        if (m.is_object() && m.contains("pbrMetallicRoughness") && m["pbrMetallicRoughness"].is_object())
            for (const char* tex : {"baseColorTexture", "metallicRoughnessTexture"})
                if (m["pbrMetallicRoughness"].contains(tex))
                    textureInfo(m["pbrMetallicRoughness"][tex], what + ": " + w + ".pbrMetallicRoughness." + tex);
    });
    eachOf(j, "skins", [&](const nlohmann::json& s, const std::string& w) {
        checkIndex(s, "inverseBindMatrices", what + ": " + w);
        checkIndex(s, "skeleton", what + ": " + w);
        checkIndexArray(s, "joints", what + ": " + w);
    });
    eachOf(j, "animations", [&](const nlohmann::json& a, const std::string& w) {
        eachOf(a, "channels", [&](const nlohmann::json& c, const std::string& cw) {
            checkIndex(c, "sampler", what + ": " + w + "." + cw);
            if (c.is_object() && c.contains("target")) checkIndex(c["target"], "node", what + ": " + w + "." + cw + ".target");
        });
        eachOf(a, "samplers", [&](const nlohmann::json& s, const std::string& sw) {
            checkIndex(s, "input", what + ": " + w + "." + sw);
            checkIndex(s, "output", what + ": " + w + "." + sw);
        });
    });
}

} // namespace

GlbChunks glbChunks(const unsigned char* data, size_t size, const std::string& what) {
    if (size < 20) throw Error(what + ": a GLB needs a 12-byte header and a JSON chunk");
    if (le32(data) != kGlbMagic) throw Error(what + ": not a GLB file (bad magic)");
    if (le32(data + 4) != 2) throw Error(what + ": GLB version " + std::to_string(le32(data + 4)) + " (only 2 is supported)");
    if (le32(data + 8) != size)
        throw Error(what + ": the GLB header says " + std::to_string(le32(data + 8)) + " bytes, the file has " +
                    std::to_string(size));
    GlbChunks c;
    size_t at = 12;
    const uint64_t jsonLen = le32(data + at);
    if (le32(data + at + 4) != kChunkJson) throw Error(what + ": the GLB's first chunk is not JSON");
    if (jsonLen > size - at - 8) throw Error(what + ": the GLB's JSON chunk runs past the end of the file");
    c.jsonAt = at + 8, c.jsonSize = size_t(jsonLen);
    at = c.jsonAt + c.jsonSize;
    if (at + 8 <= size) {
        const uint64_t binLen = le32(data + at);
        if (le32(data + at + 4) != kChunkBin) throw Error(what + ": the GLB's second chunk is not BIN");
        if (binLen > size - at - 8)
            throw Error(what + ": the GLB's BIN chunk (" + std::to_string(binLen) + " bytes) runs " +
                        std::to_string(binLen - (size - at - 8)) + " bytes past the end of the file");
        c.binAt = at + 8, c.binSize = size_t(binLen);
    } else if (at != size) {
        throw Error(what + ": " + std::to_string(size - at) + " stray bytes after the GLB's JSON chunk");
    }
    return c;
}

GuardedGltf guardGltf(const std::string& path, const SceneBudget& budget) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error("scene file not found: " + path);
    GuardedGltf g;
    g.file = fs::canonical(path, ec); // the real file: its folder is the one buffers come from
    if (ec) throw Error("scene " + path + ": " + ec.message());
    if (!fs::is_regular_file(g.file, ec)) // a folder, a FIFO (opening it would hang), ...
        throw Error("scene " + path + " is not a regular .gltf/.glb file");
    const std::string what = "cannot load glTF " + path;
    const std::string bytes = readRegularFile(g.file.string(), "scene", budget.bytes);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    g.binary = bytes.size() >= 4 && le32(data) == kGlbMagic;
    std::string json = bytes;
    GlbChunks chunks;
    if (g.binary) {
        chunks = glbChunks(data, bytes.size(), what);
        json = bytes.substr(chunks.jsonAt, chunks.jsonSize);
    } else if (const std::string kind = binaryFileKind(bytes); !kind.empty()) {
        // An image or a buffer named instead of its .gltf: said so, not "not valid JSON".
        throw Error("scene " + path + " is " + kind + ", not a glTF scene (.gltf or .glb)" +
                    (fs::path(path).extension() == ".bin" ? "; a .bin is a glTF's buffer: give the .gltf that names it"
                                                           : ""));
    }
    nlohmann::json j = parseJsonText(json, what + ":");
    if (!j.is_object()) throw Error(what + ": the JSON is not an object");
    if (!g.binary && !j.contains("asset")) // a preset or a sweep, say
        throw Error("scene " + path + " is JSON without glTF's \"asset\": not a glTF scene (.gltf or .glb)");
    checkIndices(j, what);
    if (j.contains("images")) {
        g.images = j["images"];
        j.erase("images");
    }
    g.json = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (g.binary) { // the same container around the new JSON (padded with spaces to 4 bytes)
        std::string text = g.json;
        while (text.size() % 4)
            text.push_back(' ');
        const size_t padBin = (4 - chunks.binSize % 4) % 4;
        const size_t total = 12 + 8 + text.size() + (chunks.binSize ? 8 + chunks.binSize + padBin : 0);
        g.glb.reserve(total);
        put32(g.glb, kGlbMagic), put32(g.glb, 2), put32(g.glb, uint32_t(total));
        put32(g.glb, uint32_t(text.size())), put32(g.glb, kChunkJson);
        g.glb.insert(g.glb.end(), text.begin(), text.end());
        if (chunks.binSize) {
            put32(g.glb, uint32_t(chunks.binSize + padBin)), put32(g.glb, kChunkBin);
            g.glb.insert(g.glb.end(), data + chunks.binAt, data + chunks.binAt + chunks.binSize);
            g.glb.insert(g.glb.end(), padBin, 0);
        }
    }
    return g;
}

} // namespace ssao
