// CPU scene: world-space triangles (instances flattened), grouped into draws by material.
// The same data feeds the GL renderer and the Embree reference tracer.
//
// Positions are stored relative to `origin`, a double-precision point near the scene: a scene
// placed 1e6 units from the file's origin would otherwise keep its vertices 1/16 unit apart
// (float's spacing at 1e6) and its view matrix would cancel two large numbers. Everything inside
// the renderer (vertices, bounds, cameras) is in this scene frame; only what the user reads or
// writes (--camera, preset cameras, metrics.json) is in the file's coordinates.
#pragma once
#include "scene/camera.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

struct Vertex {
    glm::vec3 position; // scene frame: file coordinates - Scene::origin (metres for glTF, mm for CAD)
    glm::vec3 normal;   // world space, unit length
};

struct Draw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    glm::vec4 baseColor{1.0f}; // glTF pbrMetallicRoughness.baseColorFactor (linear)
    // glTF alphaMode MASK: a point is cut out where baseColor.w x the alpha texture's texel there
    // (Scene::alphaTextures[alphaTexture], -1: none) is below alphaCutoff (scene/alpha_mask.h).
    bool mask = false;
    float alphaCutoff = 0.5f;
    int alphaTexture = -1;
};

// The alpha channel of a MASK material's base-colour texture, decoded (scene/load/mask_textures.h),
// with its sampler's wrap modes. Row 0 is the image's top row, at v = 0 (glTF's UV convention).
enum class Wrap : int32_t { Repeat = 0, Clamp = 1, Mirror = 2 }; // the shader's codes (alpha_mask.glsl)
struct AlphaTexture {
    int width = 0, height = 0;
    std::vector<uint8_t> alpha; // width x height, row-major
    Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
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
    // Corner i (0..7): bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
    glm::vec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
};

// glTF material classes by alphaMode (and KHR_materials_transmission, which is BLEND to a
// rasteriser), counted in triangles as loaded.
struct MaterialCounts {
    size_t opaque = 0, mask = 0, blend = 0;
    bool blendSkipped = false; // BLEND triangles left out (Transparent::Skip): not in the scene at all
    size_t maskTextures = 0, maskPixels = 0; // MASK alpha textures decoded, and their pixels
    double maskDecodeMs = 0;                 // time spent reading and decoding them
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    // Texture coordinates per vertex, only when a draw is MASK-textured (else empty): the UV set
    // its base-colour texture names, KHR_texture_transform applied.
    std::vector<glm::vec2> uvs;
    std::vector<AlphaTexture> alphaTextures;
    std::vector<uint32_t> indices;
    std::vector<Draw> draws;
    Bounds bounds;
    std::optional<Camera> camera; // the file's first camera, or a built-in scene's designed view
    std::vector<std::pair<std::string, Camera>> cameras; // every perspective camera of the file, named
    glm::dvec3 origin{0.0}; // file coordinates of the scene frame's origin
    MaterialCounts materials; // glTF scenes: what each material class holds (built-in: all opaque)

    size_t triangleCount() const { return indices.size() / 3; }
    void computeBounds();
    // Sets every vertex position from file coordinates: picks the origin (the bounds' centre when
    // the scene lies farther than its own size from the file's origin, else 0), stores positions
    // relative to it and computes the bounds. `world` has one entry per vertex. rebase = false
    // keeps the origin at 0 (float positions in file coordinates: what stress compares against).
    void setWorldPositions(const std::vector<glm::dvec3>& world, bool rebase = true);
    glm::dvec3 toWorld(const glm::vec3& p) const { return origin + glm::dvec3(p); }
    glm::vec3 toScene(const glm::dvec3& p) const { return glm::vec3(p - origin); }
};

// A camera between the file's coordinates (what --camera, presets and metrics.json hold) and the
// scene frame (what the renderer draws with).
Camera cameraToScene(const Camera& fileCamera, const Scene& s);
Camera cameraToFile(const Camera& sceneCamera, const Scene& s);

// What a scene may expand to once instances are flattened (a 1.5 KB file can list one 65k-vertex
// accessor in thousands of primitives). Loading a scene past it is a clear error naming the budget;
// `ssaolab --max-triangles N` raises it.
struct SceneBudget {
    size_t triangles = 20000000; // 20 M: ~0.5 GB of vertices and indices, plus the BVH
    // Bytes: the buffers a glTF reads (in total: two buffers naming one file count twice, a GLB its
    // whole file) and, separately, the scene they expand to (vertices, positions, indices), each
    // checked before it is allocated. `ssaolab --max-scene-mib N` raises it.
    size_t bytes = size_t(1) << 30; // 1 GiB
    // Pixels of the MASK materials' base-colour textures (the only images ssaolab decodes), in
    // total, checked from each image's header before it is decoded: 64 M pixels is eight 2K x 4K
    // textures, 256 MiB while one decodes as RGBA, 1 byte a pixel kept. `--max-mask-mpix N`.
    size_t maskPixels = size_t(64) << 20;
};
void setSceneBudget(SceneBudget b);
SceneBudget sceneBudget();

// What becomes of BLEND (and transmissive) surfaces when a glTF scene loads. Skip, the default: as
// engines draw them - after the AO, so they are neither in the G-buffer nor an occluder of the
// reference (both read the same Scene, so they agree). Opaque: drawn and traced as solids
// (`ssaolab --transparent opaque`). MASK materials are cut out either way (Draw::mask).
enum class Transparent { Skip, Opaque };
void setTransparentMode(Transparent t);
Transparent transparentMode();
Transparent parseTransparent(const std::string& s); // "skip" | "opaque", else throws naming both

} // namespace ssao
