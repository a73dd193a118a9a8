#include "scene/load/mask_textures.h"

#include "util/error.h"
#include "util/image_budget.h"

#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace ssao {

std::string percentDecode(const std::string& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out.push_back(char(hex(uri[i + 1]) * 16 + hex(uri[i + 2])));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

void encodedImage(const ImageSources& src, int image, std::vector<unsigned char>& owned, const unsigned char*& data,
                  size_t& size) {
    if (!src.images || !src.images->is_array() || image < 0 || size_t(image) >= src.images->size())
        throw Error("no such image");
    const nlohmann::json& img = (*src.images)[size_t(image)];
    if (!img.is_object()) throw Error("the image is not an object");
    if (img.contains("bufferView")) {
        if (!img["bufferView"].is_number_integer()) throw Error("its bufferView is not an index");
        const auto view = src.bufferView(img["bufferView"].get<int>());
        data = view.first, size = view.second;
        return;
    }
    if (!img.contains("uri") || !img["uri"].is_string()) throw Error("it has neither a uri nor a bufferView");
    const std::string uri = img["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) {
        std::string mime; // tinygltf's decoder: the base64 data URIs glTF allows for images
        if (!tinygltf::DecodeDataURI(&owned, mime, uri, 0, false))
            throw Error("its data URI is not a base64 image or octet-stream");
    } else {
        owned = src.readUri(percentDecode(uri));
    }
    data = owned.data(), size = owned.size();
}

std::vector<unsigned char> MaskTextures::encoded(int image, const std::string& who, const unsigned char*& data,
                                                 size_t& size) {
    const std::string at = what_ + ": image " + std::to_string(image) + " (the base-colour texture of " + who + ")";
    std::vector<unsigned char> owned;
    try {
        encodedImage(src_, image, owned, data, size);
    } catch (const Error& e) {
        throw Error(at + ": " + e.what());
    }
    return owned;
}

int MaskTextures::alphaOf(int image, Wrap s, Wrap t, const std::string& who, Scene& scene) {
    const auto key = std::make_pair(image, std::make_pair(int(s), int(t)));
    if (auto it = done_.find(key); it != done_.end()) return it->second;
    AlphaTexture tex;
    if (auto first = firstOf_.find(image); first != firstOf_.end()) {
        tex = scene.alphaTextures[size_t(first->second)]; // the same image under other wrap modes
    } else {
        const auto t0 = std::chrono::steady_clock::now();
        const unsigned char* data = nullptr;
        size_t size = 0;
        const std::vector<unsigned char> owned = encoded(image, who, data, size);
        const std::string at = what_ + ": image " + std::to_string(image) + " (the base-colour texture of " + who + ")";
        if (size > size_t(std::numeric_limits<int>::max())) throw Error(at + " is over 2 GiB");
        // Its header alone, before anything is allocated for the pixels: the size against what is
        // left of the budget, a JPEG's scans, a PNG's inflated rows (util/image_budget.h).
        checkImageBudget(data, size, ImageBudget{budget_, used_, "MASK textures", "--max-mask-mpix"}, at);
        int w = 0, h = 0, comp = 0;
        if (!stbi_info_from_memory(data, int(size), &w, &h, &comp))
            throw Error(at + " is not a PNG or JPEG that can be read (" +
                        std::string(stbi_failure_reason() ? stbi_failure_reason() : "unknown format") + ")");
        if (w <= 0 || h <= 0) throw Error(at + " has no pixels");
        const uint64_t pixels = uint64_t(w) * uint64_t(h);
        used_ += size_t(pixels);
        int w2 = 0, h2 = 0, c2 = 0;
        stbi_uc* px = stbi_load_from_memory(data, int(size), &w2, &h2, &c2, 0);
        if (!px)
            throw Error(at + " cannot be decoded (" +
                        std::string(stbi_failure_reason() ? stbi_failure_reason() : "corrupt data") + ")");
        std::vector<uint8_t> alpha;
        if (w2 != w || h2 != h) {
            stbi_image_free(px);
            throw Error(at + " decodes to another size than its header says");
        }
        if (c2 == 2 || c2 == 4) {
            alpha.resize(size_t(w) * size_t(h));
            for (size_t i = 0; i < alpha.size(); ++i)
                alpha[i] = px[i * size_t(c2) + size_t(c2 - 1)];
        } else {
            alpha.assign(1, 255); // no alpha channel: opaque everywhere, one texel holds it
            w2 = h2 = 1;
        }
        stbi_image_free(px);
        tex.width = w2, tex.height = h2;
        tex.alpha = std::move(alpha);
        scene.materials.maskPixels += size_t(pixels);
        scene.materials.maskDecodeMs +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    tex.wrapS = s, tex.wrapT = t;
    scene.alphaTextures.push_back(std::move(tex));
    ++scene.materials.maskTextures;
    const int index = int(scene.alphaTextures.size()) - 1;
    firstOf_.emplace(image, index);
    done_[key] = index;
    return index;
}

} // namespace ssao
