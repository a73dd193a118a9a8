#include "scene/load/gltf_accessors.h"

#include "util/error.h"

#include <cmath>

namespace ssao {

const unsigned char* accessorData(const tinygltf::Model& m, const tinygltf::Accessor& a,
                                  const std::string& what, size_t elemSize, size_t& stride) {
    if (a.sparse.isSparse) throw Error(what + ": sparse accessors are not supported");
    if (a.bufferView < 0 || a.bufferView >= int(m.bufferViews.size()))
        throw Error(what + ": accessor has no bufferView");
    const auto& bv = m.bufferViews[a.bufferView];
    if (bv.buffer < 0 || bv.buffer >= int(m.buffers.size())) throw Error(what + ": bufferView has no buffer");
    const auto& buf = m.buffers[bv.buffer];
    stride = bv.byteStride ? bv.byteStride : elemSize;
    // Every size here comes from the file: check in a form that cannot wrap around (offsets near
    // 2^64 or counts near 2^62 would otherwise pass a naive `offset + size <= length`).
    const size_t bufLen = buf.data.size();
    if (bv.byteOffset > bufLen || bv.byteLength > bufLen - bv.byteOffset)
        throw Error(what + ": bufferView lies outside its buffer");
    if (bv.byteStride && (bv.byteStride < elemSize || bv.byteStride > 252)) // glTF: [4, 252]
        throw Error(what + ": byteStride " + std::to_string(bv.byteStride) + " is invalid");
    if (a.byteOffset > bv.byteLength) throw Error(what + ": accessor starts past the end of its bufferView");
    const size_t room = bv.byteLength - a.byteOffset; // bytes the accessor may read
    if (a.count > 0 && (elemSize > room || a.count - 1 > (room - elemSize) / stride))
        throw Error(what + ": accessor reads past the end of its buffer");
    const size_t begin = bv.byteOffset + a.byteOffset;
    return buf.data.data() + begin;
}

Vec3Reader vec3Accessor(const tinygltf::Model& m, int index, const std::string& what) {
    if (index < 0 || index >= int(m.accessors.size())) throw Error(what + ": bad accessor index");
    const auto& a = m.accessors[index];
    if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.normalized)
        throw Error(what +
                    ": only float VEC3 is supported (quantized attributes need KHR_mesh_quantization)");
    Vec3Reader r;
    r.count = a.count;
    r.base = accessorData(m, a, what, sizeof(glm::vec3), r.stride);
    return r;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& m, const tinygltf::Primitive& p, size_t vertexCount,
                                  const std::string& what) {
    std::vector<uint32_t> idx;
    if (p.indices < 0) {
        idx.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i)
            idx[i] = uint32_t(i);
        return idx;
    }
    if (p.indices >= int(m.accessors.size())) throw Error(what + ": bad index accessor");
    const auto& a = m.accessors[p.indices];
    size_t size = 0;
    switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        size = 1;
        break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        size = 2;
        break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        size = 4;
        break;
    default:
        throw Error(what + ": index component type " + std::to_string(a.componentType) +
                    " is not an unsigned integer");
    }
    size_t stride = 0;
    const unsigned char* data = accessorData(m, a, what + " indices", size, stride);
    idx.resize(a.count);
    for (size_t i = 0; i < a.count; ++i) {
        const unsigned char* e = data + i * stride;
        uint32_t v = size == 1   ? *e
                     : size == 2 ? uint32_t(e[0] | (e[1] << 8))
                                 : uint32_t(e[0] | (e[1] << 8) | (e[2] << 16) | (uint32_t(e[3]) << 24));
        if (v >= vertexCount) throw Error(what + ": index " + std::to_string(v) + " out of range");
        idx[i] = v;
    }
    return idx;
}

std::vector<glm::vec2> vec2Accessor(const tinygltf::Model& m, int index, const std::string& what) {
    if (index < 0 || index >= int(m.accessors.size())) throw Error(what + ": bad accessor index");
    const auto& a = m.accessors[size_t(index)];
    size_t comp = 0;
    double scale = 1.0;
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) comp = 4;
    else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a.normalized) comp = 1, scale = 1.0 / 255.0;
    else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && a.normalized) comp = 2, scale = 1.0 / 65535.0;
    if (a.type != TINYGLTF_TYPE_VEC2 || comp == 0)
        throw Error(what + ": only float or normalised unsigned byte/short VEC2 texture coordinates are supported");
    size_t stride = 0;
    const unsigned char* data = accessorData(m, a, what, 2 * comp, stride);
    std::vector<glm::vec2> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
        const unsigned char* e = data + i * stride;
        for (int k = 0; k < 2; ++k) {
            const unsigned char* c = e + size_t(k) * comp;
            double v = 0;
            if (comp == 4) {
                float f;
                std::memcpy(&f, c, 4);
                v = std::isfinite(f) ? f : 0.0f;
            } else {
                v = (comp == 1 ? double(c[0]) : double(c[0] | (c[1] << 8))) * scale;
            }
            out[i][k] = float(v);
        }
    }
    return out;
}

} // namespace ssao
