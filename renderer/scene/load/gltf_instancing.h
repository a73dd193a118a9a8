// EXT_mesh_gpu_instancing: a node drawing its mesh once per instance, each instance's transform
// (TRANSLATION, ROTATION, SCALE accessors) applied in the node's local frame before the node's own
// (world = node's world x T x R x S). ssaolab expands instances into triangles, within the scene's
// triangle budget (which bounds the instances too: each is at least a triangle's work), so the
// G-buffer and the reference hold the same surfaces; a primitive's instances make one draw.
#pragma once
#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace ssao {

// The instances a node's mesh is drawn with: 1 without the extension. From the accessors' counts
// alone (checked equal), so the budget is checked before anything is read or allocated.
size_t instanceCount(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what);

// Each instance's transform in the node's local frame (one identity without the extension), read
// when asked for: nothing is allocated per instance. The accessors are checked when it is made
// (throws ssao::Error naming the one that cannot be read); a non-finite element when it is read.
class InstanceTransforms {
  public:
    InstanceTransforms(const tinygltf::Model& m, const tinygltf::Node& n, const std::string& what);
    size_t count() const { return count_; }
    glm::dmat4 operator[](size_t i) const;

  private:
    struct Attribute { // one of TRANSLATION, ROTATION, SCALE (data null: absent)
        const unsigned char* data = nullptr;
        size_t stride = 0, componentBytes = 0;
        int components = 0;
        std::string what;
        glm::dvec4 at(size_t i) const;
    };
    Attribute translation_, rotation_, scale_;
    size_t count_ = 1;
};

} // namespace ssao
