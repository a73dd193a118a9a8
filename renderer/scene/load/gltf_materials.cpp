#include "scene/load/gltf_materials.h"

#include "scene/load/gltf_accessors.h"
#include "util/error.h"

#include <cmath>

namespace ssao {

MaterialClass materialClass(const tinygltf::Material* m) {
    if (!m) return MaterialClass::Opaque;
    // KHR_materials_transmission: a rasteriser draws it as a transparent pass, like BLEND.
    if (m->alphaMode == "BLEND" || m->extensions.count("KHR_materials_transmission")) return MaterialClass::Blend;
    if (m->alphaMode == "MASK") return MaterialClass::Mask;
    return MaterialClass::Opaque;
}

namespace {

Wrap wrapOf(int glWrap) {
    switch (glWrap) {
    case 33071: // CLAMP_TO_EDGE
        return Wrap::Clamp;
    case 33648: // MIRRORED_REPEAT
        return Wrap::Mirror;
    default: // REPEAT (10497), the default
        return Wrap::Repeat;
    }
}

double number(const tinygltf::Value& v, double fallback) {
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

// KHR_texture_transform (ratified): uv' = T(offset) R(rotation) S(scale) uv, rotation
// counter-clockwise in the image (its matrix is [cos sin; -sin cos] applied to (u, v)).
struct UvTransform {
    glm::vec2 offset{0.0f}, scale{1.0f};
    float rotation = 0.0f;
    int texCoord = -1; // overrides textureInfo.texCoord when set
    glm::vec2 apply(glm::vec2 uv) const {
        const glm::vec2 s = uv * scale;
        const float c = std::cos(rotation), n = std::sin(rotation);
        return glm::vec2(c * s.x + n * s.y, -n * s.x + c * s.y) + offset;
    }
};

UvTransform transformOf(const tinygltf::TextureInfo& info) {
    UvTransform t;
    const auto it = info.extensions.find("KHR_texture_transform");
    if (it == info.extensions.end() || !it->second.IsObject()) return t;
    const tinygltf::Value& x = it->second;
    auto pair = [&](const char* key, glm::vec2 fallback) {
        if (!x.Has(key) || !x.Get(key).IsArray() || x.Get(key).ArrayLen() != 2) return fallback;
        return glm::vec2(float(number(x.Get(key).Get(0), fallback.x)), float(number(x.Get(key).Get(1), fallback.y)));
    };
    t.offset = pair("offset", t.offset);
    t.scale = pair("scale", t.scale);
    if (x.Has("rotation")) t.rotation = float(number(x.Get("rotation"), 0.0));
    if (x.Has("texCoord") && x.Get("texCoord").IsInt()) t.texCoord = x.Get("texCoord").GetNumberAsInt();
    return t;
}

} // namespace

std::vector<glm::vec2> maskAlphaTest(const tinygltf::Model& m, const tinygltf::Primitive& p,
                                     const tinygltf::Material& mat, size_t vertexCount, Draw& d,
                                     MaskTextures& textures, Scene& s, const std::string& what) {
    d.mask = true;
    d.alphaCutoff = float(mat.alphaCutoff);
    if (!std::isfinite(d.alphaCutoff)) d.alphaCutoff = 0.5f;
    const tinygltf::TextureInfo& info = mat.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return {}; // the factor's alpha alone decides, for the whole primitive
    const std::string who = "material '" + (mat.name.size() > 60 ? mat.name.substr(0, 57) + "..." : mat.name) + "'";
    if (info.index >= int(m.textures.size())) throw Error(what + ": " + who + " names texture " + std::to_string(info.index) + ", which does not exist");
    const tinygltf::Texture& tex = m.textures[size_t(info.index)];
    if (tex.source < 0)
        throw Error(what + ": the base-colour texture of " + who +
                    " has no PNG or JPEG source (only an extension's image format), so its cut-out cannot be read");
    Wrap ws = Wrap::Repeat, wt = Wrap::Repeat;
    if (tex.sampler >= 0 && tex.sampler < int(m.samplers.size()))
        ws = wrapOf(m.samplers[size_t(tex.sampler)].wrapS), wt = wrapOf(m.samplers[size_t(tex.sampler)].wrapT);
    const UvTransform xf = transformOf(info);
    const int set = xf.texCoord >= 0 ? xf.texCoord : info.texCoord;
    const auto uvIt = p.attributes.find("TEXCOORD_" + std::to_string(set));
    if (uvIt == p.attributes.end())
        throw Error(what + ": " + who + " reads TEXCOORD_" + std::to_string(set) + ", which the primitive does not have");
    std::vector<glm::vec2> uv = vec2Accessor(m, uvIt->second, what + " TEXCOORD_" + std::to_string(set));
    if (uv.size() != vertexCount) throw Error(what + ": TEXCOORD_" + std::to_string(set) + " count differs from POSITION count");
    for (auto& q : uv)
        q = xf.apply(q);
    d.alphaTexture = textures.alphaOf(tex.source, ws, wt, who, s);
    return uv;
}

} // namespace ssao
