// CPU scene: world-space triangles (instances flattened), grouped into draws by material.
// The same data feeds the GL renderer and, later, the Embree reference tracer.
#pragma once
#include "scene/camera.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct Vertex {
    glm::vec3 position; // world space (scene units: metres for glTF, mm for the CAD scenes)
    glm::vec3 normal;   // world space, unit length
};

struct Draw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    glm::vec4 baseColor{1.0f}; // glTF pbrMetallicRoughness.baseColorFactor (linear)
};

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    void add(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    bool valid() const { return min.x <= max.x; }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    float radius() const { return glm::length(max - min) * 0.5f; }
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Draw> draws;
    Bounds bounds;
    std::optional<Camera> camera; // the file's first camera, or a built-in scene's designed view
    std::vector<std::pair<std::string, Camera>> cameras; // every perspective camera of the file, named

    size_t triangleCount() const { return indices.size() / 3; }
    void computeBounds();
};

// What a scene may expand to once instances are flattened (a 1.5 KB file can list one 65k-vertex
// accessor in thousands of primitives). Loading a scene past it is a clear error naming the budget;
// `ssaolab --max-triangles N` raises it.
struct SceneBudget {
    size_t triangles = 20000000; // 20 M: ~0.5 GB of vertices and indices, plus the BVH
};
void setSceneBudget(SceneBudget b);
SceneBudget sceneBudget();

// "builtin:NAME" → procedural scene, anything else → glTF file. Throws ssao::Error.
Scene loadScene(const std::string& spec);

} // namespace ssao
