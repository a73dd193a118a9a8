#include "scene/load/browser_assets.h"

#include "scene/load/gltf_files.h"
#include "scene/load/gltf_guard.h"
#include "scene/load/mask_textures.h"
#include "util/error.h"
#include "util/image_budget.h"

namespace ssao {

namespace {

// RFC 3986 scheme: a letter, then letters, digits, + - . up to the ':'.
bool hasScheme(const std::string& uri) {
    const size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0) return false;
    for (size_t i = 0; i < colon; ++i) {
        const char c = uri[i];
        const bool alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
        if (!alpha && (i == 0 || !((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'))) return false;
    }
    return true;
}

std::string clipped(const std::string& uri) {
    std::string s = uri.size() > 120 ? uri.substr(0, 120) + "..." : uri;
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return s;
}

} // namespace

std::string servedRelativePath(const std::string& uri) {
    if (hasScheme(uri) || uri.rfind("//", 0) == 0 || uri.rfind("/", 0) == 0 || uri.rfind("\\", 0) == 0)
        throw Error("'" + clipped(uri) + "' is a network or absolute URI; the engine's browser loads only files inside the scene's folder");
    // A query or fragment, a '+' (a space to tinygltf, itself to the browser) or a control character
    // (dropped by the browser's URL parser): each would be read as another file by another reader.
    for (char c : uri)
        if (c == '?' || c == '#' || c == '+' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            throw Error("'" + clipped(uri) + "' holds a '?', '#', '+' or a control character, which the browser and "
                        "ssaolab would read as different files");
    const std::string& raw = uri;
    std::string path;
    size_t start = 0;
    for (;;) {
        const size_t slash = raw.find('/', start);
        const std::string part = percentDecode(raw.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
        if (part.empty() || part == ".." || part.find_first_of(std::string("/\\\0", 3)) != std::string::npos)
            throw Error("'" + clipped(uri) + "' leaves the scene's folder or names a folder (an empty or '..' component, "
                        "or an encoded separator)");
        if (part != ".") path += (path.empty() ? "" : "/") + part; // dropped, as the browser drops it
        if (slash == std::string::npos && path.empty())
            throw Error("'" + clipped(uri) + "' names the scene's folder, not a file");
        if (slash == std::string::npos) return path;
        start = slash + 1;
    }
}

void checkBrowserAssets(const std::string& sceneFile) {
    const SceneBudget budget = sceneBudget();
    const GuardedGltf g = guardGltf(sceneFile, budget);
    SceneFolder folder{g.file.parent_path(), budget.bytes, 0};
    const tinygltf::Model model = readModel(g, sceneFile, folder); // its buffers: inside the folder and budget
    const std::string what = "glTF " + sceneFile + " in the engine's browser";
    for (size_t i = 0; i < model.buffers.size(); ++i) {
        const std::string& uri = model.buffers[i].uri;
        if (uri.empty() || uri.rfind("data:", 0) == 0) continue;
        try {
            servedRelativePath(uri);
        } catch (const Error& e) {
            throw Error(what + ": buffer " + std::to_string(i) + ": " + e.what());
        }
    }
    const ImageSources src = imageSources(g, model, folder);
    ImageBudget images{budget.maskPixels, 0, "images the engine's browser decodes", "--max-mask-mpix"};
    for (size_t i = 0; g.images.is_array() && i < g.images.size(); ++i) {
        const std::string at = what + ": image " + std::to_string(i);
        const nlohmann::json& img = g.images[i];
        if (img.is_object() && img.contains("uri") && img["uri"].is_string() && img["uri"].get<std::string>().rfind("data:", 0) != 0) {
            try {
                servedRelativePath(img["uri"].get<std::string>());
            } catch (const Error& e) {
                throw Error(at + ": " + e.what());
            }
        }
        std::vector<unsigned char> owned;
        const unsigned char* data = nullptr;
        size_t size = 0;
        try {
            encodedImage(src, int(i), owned, data, size);
        } catch (const Error& e) {
            throw Error(at + ": " + e.what());
        }
        const ImageHeader h = checkImageBudget(data, size, images, at);
        if (h.pixels() == 0) // WebP, KTX2 and the like: a browser decodes what ssaolab cannot size
            throw Error(at + ": its format gives no size ssaolab can check before the browser decodes it (PNG and JPEG do)");
        images.used += h.pixels();
    }
}

} // namespace ssao
