// What a glTF may read besides itself, for tinygltf's file callbacks and the MASK textures
// (mask_textures.h): regular files under the scene's own folder, within one byte budget.
#pragma once
#include "scene/load/gltf_guard.h"
#include "scene/load/mask_textures.h"

#include <tiny_gltf.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ssao {

// Files a glTF may read: regular files under its own folder, at most 2 GiB. A buffer uri like
// "../../etc/passwd", an absolute path, a folder or a FIFO (which would block forever) is refused
// with a message naming it, instead of being read or hanging.
struct SceneFolder {
    std::filesystem::path root; // canonical
    size_t budget = 0;          // bytes every buffer read may take in total
    size_t read = 0;            // bytes read so far
};

// tinygltf's file callbacks (user data: the SceneFolder).
bool fileExistsInFolder(const std::string& file, void*);
std::string keepPath(const std::string& file, void*);
bool readFileInFolder(std::vector<unsigned char>* out, std::string* err, const std::string& file, void* folder);
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*);
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*);

// The file as tinygltf reads it (gltf_loader.cpp): regular files only, buffers inside the scene's
// folder and byte budget, images never decoded; glTF 1.0 and geometry-changing extensions refused.
tinygltf::Model readModel(const GuardedGltf& g, const std::string& path, SceneFolder& folder);

// Where the MASK textures' bytes come from: files through the same folder and byte budget as the
// buffers, bufferViews checked to lie inside their buffer.
ImageSources imageSources(const GuardedGltf& g, const tinygltf::Model& model, SceneFolder& folder);

} // namespace ssao
