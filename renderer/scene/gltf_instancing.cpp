#include "scene/gltf_instancing.h"

#include "scene/gltf_accessors.h"
#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ssao {

namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

// attribute name -> accessor index (-1: absent), validated as indices.
int attribute(const tinygltf::Model& m, const tinygltf::Value& attrs, const char* name, const std::string& what) {
    if (!attrs.Has(name)) return -1;
    const tinygltf::Value& v = attrs.Get(name);
    if (!v.IsInt() || v.GetNumberAsInt() < 0 || v.GetNumberAsInt() >= int(m.accessors.size()))
        throw Error(what + ": " + kExtension + " attribute " + name + " is not an accessor of the file");
    return v.GetNumberAsInt();
}

const tinygltf::Value* attributesOf(const tinygltf::Node& n, const std::string& what) {
    const auto it = n.extensions.find(kExtension);
    if (it == n.extensions.end()) return nullptr;
    if (!it->second.IsObject() || !it->second.Has("attributes") || !it->second.Get("attributes").IsObject())
        throw Error(what + ": " + kExtension + " has no attributes object");
    return &it->second.Get("attributes");
}

// Element i of a VEC3/VEC4 accessor as doubles: float, or (ROTATION) normalised signed byte/short.
std::vector<glm::dvec4> readVectors(const tinygltf::Model& m, int index, int components, bool normalisedOk,
                                    const std::string& what) {
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    const int type = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
    size_t comp = 0;
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) comp = 4;
    else if (normalisedOk && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE) comp = 1;
    else if (normalisedOk && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) comp = 2;
    if (a.type != type || comp == 0)
        throw Error(what + ": only float" + std::string(normalisedOk ? " or normalised byte/short" : "") + " VEC" +
                    std::to_string(components) + " is supported");
    size_t stride = 0;
    const unsigned char* data = accessorData(m, a, what, comp * size_t(components), stride);
    std::vector<glm::dvec4> out(a.count, glm::dvec4(0.0));
    for (size_t i = 0; i < a.count; ++i)
        for (int k = 0; k < components; ++k) {
            const unsigned char* c = data + i * stride + size_t(k) * comp;
            double v = 0;
            if (comp == 4) {
                float f;
                std::memcpy(&f, c, 4);
                v = f;
            } else if (comp == 1) {
                v = std::max(double(int8_t(c[0])) / 127.0, -1.0);
            } else {
                int16_t s;
                std::memcpy(&s, c, 2);
                v = std::max(double(s) / 32767.0, -1.0);
            }
            if (!std::isfinite(v)) throw Error(what + ": element " + std::to_string(i) + " is not finite");
            out[i][k] = v;
        }
    return out;
}

} // namespace

size_t instanceCount(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what) {
    const tinygltf::Value* attrs = attributesOf(n, what);
    if (!attrs) return 1;
    size_t count = 0;
    bool any = false;
    for (const char* name : {"TRANSLATION", "ROTATION", "SCALE"}) {
        const int a = attribute(m, *attrs, name, what);
        if (a < 0) continue;
        const size_t c = m.accessors[size_t(a)].count;
        if (any && c != count)
            throw Error(what + ": " + kExtension + " attributes have different counts (" + std::to_string(count) + " and " +
                        std::to_string(c) + ")");
        count = c, any = true;
    }
    if (!any) throw Error(what + ": " + kExtension + " names none of TRANSLATION, ROTATION, SCALE");
    return count;
}

std::vector<glm::dmat4> instanceTransforms(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what) {
    const tinygltf::Value* attrs = attributesOf(n, what);
    if (!attrs) return {glm::dmat4(1.0)};
    const size_t count = instanceCount(m, n, what);
    const int t = attribute(m, *attrs, "TRANSLATION", what), r = attribute(m, *attrs, "ROTATION", what),
              s = attribute(m, *attrs, "SCALE", what);
    const std::string at = what + " " + kExtension;
    const auto tv = t >= 0 ? readVectors(m, t, 3, false, at + " TRANSLATION") : std::vector<glm::dvec4>();
    const auto rv = r >= 0 ? readVectors(m, r, 4, true, at + " ROTATION") : std::vector<glm::dvec4>();
    const auto sv = s >= 0 ? readVectors(m, s, 3, false, at + " SCALE") : std::vector<glm::dvec4>();
    std::vector<glm::dmat4> out(count, glm::dmat4(1.0));
    for (size_t i = 0; i < count; ++i) {
        glm::dmat4 x(1.0);
        if (!tv.empty()) x = glm::translate(x, glm::dvec3(tv[i]));
        if (!rv.empty()) { // (x, y, z, w) unit quaternion; renormalised (quantised ones are not unit)
            glm::dquat q(rv[i].w, rv[i].x, rv[i].y, rv[i].z);
            const double len = glm::length(q);
            x *= len > 1e-12 ? glm::mat4_cast(q / len) : glm::dmat4(1.0);
        }
        if (!sv.empty()) x = glm::scale(x, glm::dvec3(sv[i]));
        out[i] = x;
    }
    return out;
}

} // namespace ssao
