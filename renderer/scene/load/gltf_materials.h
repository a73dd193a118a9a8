// What a glTF material does to the surfaces ssaolab draws and traces: its class (opaque, MASK,
// BLEND/transmissive: scene.h Transparent) and, for MASK, the alpha test of Draw::mask with the
// texture coordinates its base-colour texture reads.
#pragma once
#include "scene/load/mask_textures.h"
#include "scene/scene.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace ssao {

enum class MaterialClass { Opaque, Mask, Blend };
MaterialClass materialClass(const tinygltf::Material* m);

// Fills d's alpha test from a MASK material (cutoff, factor alpha in d.baseColor, the decoded
// alpha texture) and returns the primitive's texture coordinates, one per vertex of its POSITION
// accessor (`vertexCount`), with KHR_texture_transform applied; empty when no texture is read.
// Throws ssao::Error naming the material for a texture it cannot read.
std::vector<glm::vec2> maskAlphaTest(const tinygltf::Model& m, const tinygltf::Primitive& p,
                                     const tinygltf::Material& mat, size_t vertexCount, Draw& d,
                                     MaskTextures& textures, Scene& s, const std::string& what);

} // namespace ssao
