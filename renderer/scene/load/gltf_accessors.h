// Reading glTF accessors with every size the file gives checked in a form that cannot wrap.
#pragma once
#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstring>
#include <string>
#include <vector>

namespace ssao {

// Reads element i of a float VEC3 accessor honouring byteStride.
struct Vec3Reader {
    const unsigned char* base = nullptr;
    size_t stride = 0;
    size_t count = 0;
    glm::vec3 operator[](size_t i) const {
        glm::vec3 v;
        std::memcpy(&v, base + i * stride, sizeof v);
        return v;
    }
};

// The first byte of accessor `a`'s data, with its stride; throws ssao::Error (prefixed `what`)
// when it would read outside its bufferView or buffer.
const unsigned char* accessorData(const tinygltf::Model& m, const tinygltf::Accessor& a, const std::string& what,
                                  size_t elemSize, size_t& stride);
Vec3Reader vec3Accessor(const tinygltf::Model& m, int index, const std::string& what);
// TEXCOORD_n: float, or normalised unsigned byte/short VEC2 (glTF 2.0 §3.7.2.1), as floats.
std::vector<glm::vec2> vec2Accessor(const tinygltf::Model& m, int index, const std::string& what);
std::vector<uint32_t> readIndices(const tinygltf::Model& m, const tinygltf::Primitive& p, size_t vertexCount,
                                  const std::string& what);

} // namespace ssao
