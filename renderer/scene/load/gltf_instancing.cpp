#include "scene/load/gltf_instancing.h"

#include "scene/load/gltf_accessors.h"
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

InstanceTransforms::InstanceTransforms(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what) {
    const tinygltf::Value* attrs = attributesOf(n, what);
    if (!attrs) return;
    count_ = instanceCount(m, n, what);
    const std::string at = what + " " + kExtension;
    // VEC3/VEC4 accessors of float, or (ROTATION) normalised signed byte/short.
    auto open = [&](const char* name, int components, bool normalisedOk) {
        Attribute r;
        const int index = attribute(m, *attrs, name, what);
        if (index < 0) return r;
        const tinygltf::Accessor& a = m.accessors[size_t(index)];
        const int type = components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) r.componentBytes = 4;
        else if (normalisedOk && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE) r.componentBytes = 1;
        else if (normalisedOk && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) r.componentBytes = 2;
        r.what = at + " " + name;
        if (a.type != type || r.componentBytes == 0)
            throw Error(r.what + ": only float" + std::string(normalisedOk ? " or normalised byte/short" : "") + " VEC" +
                        std::to_string(components) + " is supported");
        r.components = components;
        r.data = accessorData(m, a, r.what, r.componentBytes * size_t(components), r.stride);
        return r;
    };
    translation_ = open("TRANSLATION", 3, false);
    rotation_ = open("ROTATION", 4, true);
    scale_ = open("SCALE", 3, false);
}

glm::dvec4 InstanceTransforms::Attribute::at(size_t i) const {
    glm::dvec4 out(0.0);
    for (int k = 0; k < components; ++k) {
        const unsigned char* c = data + i * stride + size_t(k) * componentBytes;
        double v = 0;
        if (componentBytes == 4) {
            float f;
            std::memcpy(&f, c, 4);
            v = f;
        } else if (componentBytes == 1) {
            v = std::max(double(int8_t(c[0])) / 127.0, -1.0);
        } else {
            int16_t s;
            std::memcpy(&s, c, 2);
            v = std::max(double(s) / 32767.0, -1.0);
        }
        if (!std::isfinite(v)) throw Error(what + ": element " + std::to_string(i) + " is not finite");
        out[k] = v;
    }
    return out;
}

glm::dmat4 InstanceTransforms::operator[](size_t i) const {
    glm::dmat4 x(1.0);
    if (translation_.data) x = glm::translate(x, glm::dvec3(translation_.at(i)));
    if (rotation_.data) { // (x, y, z, w) unit quaternion; renormalised (quantised ones are not unit)
        const glm::dvec4 r = rotation_.at(i);
        glm::dquat q(r.w, r.x, r.y, r.z);
        const double len = glm::length(q);
        x *= len > 1e-12 ? glm::mat4_cast(q / len) : glm::dmat4(1.0);
    }
    if (scale_.data) x = glm::scale(x, glm::dvec3(scale_.at(i)));
    return x;
}

} // namespace ssao
