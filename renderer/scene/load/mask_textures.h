// The only images ssaolab decodes: the base-colour textures of MASK materials, for their alpha.
// Every other image stays undecoded and unread (gltf_guard.h takes them out of what tinygltf
// parses). Each image is checked before it is decoded (util/image_budget.h): its header's size
// against the scene's budget of MASK pixels (SceneBudget::maskPixels), so a 200-byte header claiming
// 23000 x 23000 is refused by name, as are a JPEG of thousands of scans, a PNG whose data inflates
// past its header, truncated data, a bufferView outside its buffer and formats stb cannot read.
#pragma once
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ssao {

struct ImageSources {
    // The file's `images` array as written (gltf_guard.h).
    const nlohmann::json* images = nullptr;
    // The bytes of a file the image's uri names (percent-decoded, relative to the scene's folder),
    // read within the scene's folder and byte budget; throws ssao::Error naming why not.
    std::function<std::vector<unsigned char>(const std::string& uri)> readUri;
    // The bytes of bufferView i, checked to lie inside its buffer; throws ssao::Error naming why not.
    std::function<std::pair<const unsigned char*, size_t>(int bufferView)> bufferView;
};

class MaskTextures {
  public:
    MaskTextures(ImageSources sources, size_t pixelBudget, std::string what)
        : src_(std::move(sources)), budget_(pixelBudget), what_(std::move(what)) {}
    // The index in scene.alphaTextures of image `image`'s alpha with these wrap modes, decoded the
    // first time it is asked for; `user` names who asked ("material 'Leaves'") in errors.
    int alphaOf(int image, Wrap s, Wrap t, const std::string& user, Scene& scene);

  private:
    std::vector<unsigned char> encoded(int image, const std::string& who, const unsigned char*& data, size_t& size);
    ImageSources src_;
    size_t budget_, used_ = 0;
    std::string what_;
    std::map<std::pair<int, std::pair<int, int>>, int> done_;  // (image, wrap) -> index
    std::map<int, int> firstOf_; // image -> its first entry in scene.alphaTextures (decoded once)
};

std::string percentDecode(const std::string& uri);

// The encoded bytes of image `image` of `src`: a view of its bufferView (`data`, `size`) or the
// bytes of its data URI or file in `owned`. Throws ssao::Error saying why not (no image, no uri nor
// bufferView, a bad data URI, a file outside the folder or its budget).
void encodedImage(const ImageSources& src, int image, std::vector<unsigned char>& owned, const unsigned char*& data,
                  size_t& size);

} // namespace ssao
