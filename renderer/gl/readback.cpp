#include "gl/readback.h"

#include <algorithm>

namespace ssao {

Image readBack(const gl::Texture2D& tex, int channels) {
    Image img{tex.width(), tex.height(), channels, {}};
    std::vector<float> raw = tex.readFloats(channels);
    img.data.resize(raw.size());
    const size_t row = size_t(img.width) * channels;
    for (int y = 0; y < img.height; ++y)
        std::copy_n(raw.begin() + ptrdiff_t(size_t(img.height - 1 - y) * row), row,
                    img.data.begin() + ptrdiff_t(size_t(y) * row));
    return img;
}

} // namespace ssao
