// What a glTF file must pass before tinygltf sees it - the checks its parser does not make, each
// a class of hostile file found by hand or by fuzzing (issues 9 and 16):
//  - the path is resolved first (a scene opened through a symlink looks for its buffers beside its
//    target, the one folder buffers may come from), and must be a regular file within the budget;
//  - a GLB's header and chunk lengths lie inside the file (a BIN chunk 8 bytes too long made
//    tinygltf read past its heap buffer, and the bytes became a triangle);
//  - JSON nesting is bounded (20 000 nested `extras` arrays overflowed tinygltf's recursion);
//  - every index is an integer in [0, 2^31) before tinygltf narrows it to int (4294967296 wrapped
//    to 0 and drew another object in its place);
//  - images are taken out: ssaolab decodes none, and tinygltf would read every external image
//    file whole (64 images naming one sparse 2 GiB file: minutes and 2 GiB).
#pragma once
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ssao {

struct GuardedGltf {
    std::filesystem::path file; // canonical: symlinks resolved
    bool binary = false;
    std::string json;                // what tinygltf parses (images removed)
    std::vector<unsigned char> glb;  // GLB: the file rebuilt around that JSON (its BIN chunk as is)
    nlohmann::json images;           // the file's images, as they were
};

// Throws ssao::Error naming the file and the problem.
GuardedGltf guardGltf(const std::string& path, const SceneBudget& budget);

// The GLB container's chunks, validated against the file's size: JSON [jsonAt, jsonAt + jsonSize),
// BIN [binAt, binAt + binSize) (binSize 0: none). Throws naming what is wrong.
struct GlbChunks {
    size_t jsonAt = 0, jsonSize = 0, binAt = 0, binSize = 0;
};
GlbChunks glbChunks(const unsigned char* data, size_t size, const std::string& what);

} // namespace ssao
