#include "scene/load/gltf_files.h"

#include "util/error.h"
#include "util/files.h"

#include <algorithm>

namespace ssao {

namespace {

std::optional<std::filesystem::path> insideFolder(const std::string& file, const SceneFolder& f) {
    std::error_code ec;
    const auto p = std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec);
    if (ec) return std::nullopt;
    auto r = f.root.begin();
    auto q = p.begin();
    for (; r != f.root.end(); ++r, ++q)
        if (q == p.end() || *q != *r) return std::nullopt;
    return p;
}

} // namespace

// Says yes for any existing path, so that the read below refuses it with a precise reason.
bool fileExistsInFolder(const std::string& file, void*) {
    std::error_code ec;
    return std::filesystem::exists(file, ec);
}

std::string keepPath(const std::string& file, void*) {
    return file; // no ~ or $VAR expansion of paths that come from a file
}

bool readFileInFolder(std::vector<unsigned char>* out, std::string* err, const std::string& file,
                      void* user) {
    const auto* folder = static_cast<SceneFolder*>(user);
    const auto p = insideFolder(file, *folder);
    if (!p) {
        if (err) *err += "'" + file + "' is outside the scene's folder " + folder->root.string() + "\n";
        return false;
    }
    // The budget counts every read, before it happens: two buffers naming one sparse 2 GiB file
    // would take 4 GiB.
    auto* f = static_cast<SceneFolder*>(user);
    const size_t left = f->budget - std::min(f->read, f->budget);
    try {
        const std::string bytes = readRegularFile(p->string(), "'" + file + "'", left);
        f->read += bytes.size();
        out->assign(bytes.begin(), bytes.end());
    } catch (const FileTooLarge&) {
        if (err)
            *err += "'" + file + "' takes the scene's buffers past the budget of " + std::to_string(f->budget >> 20) +
                    " MiB (raise it with ssaolab --max-scene-mib N)\n";
        return false;
    } catch (const Error& e) {
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "ssaolab never writes glTF files\n";
    return false;
}

// Images are never decoded: ssaolab shades with base-colour factors only, and a 200-byte header can
// claim 23000x23000 pixels (4 GB), or point its bufferView outside its buffer.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// Where the MASK textures' bytes come from: files through the same folder and byte budget as the
// buffers, bufferViews checked to lie inside their buffer.
ImageSources imageSources(const GuardedGltf& g, const tinygltf::Model& model, SceneFolder& folder) {
    ImageSources src;
    src.images = &g.images;
    src.readUri = [&folder](const std::string& uri) {
        std::vector<unsigned char> bytes;
        std::string err;
        const std::string file = (folder.root / uri).string();
        if (!readFileInFolder(&bytes, &err, file, &folder)) {
            while (!err.empty() && err.back() == '\n')
                err.pop_back();
            throw Error(err);
        }
        return bytes;
    };
    src.bufferView = [&model](int i) {
        if (i < 0 || i >= int(model.bufferViews.size())) throw Error("bufferView " + std::to_string(i) + " does not exist");
        const auto& bv = model.bufferViews[size_t(i)];
        if (bv.buffer < 0 || bv.buffer >= int(model.buffers.size())) throw Error("its bufferView has no buffer");
        const size_t len = model.buffers[size_t(bv.buffer)].data.size();
        if (bv.byteOffset > len || bv.byteLength > len - bv.byteOffset)
            throw Error("its bufferView " + std::to_string(i) + " lies outside its buffer");
        return std::make_pair(model.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset, size_t(bv.byteLength));
    };
    return src;
}

} // namespace ssao
