#include "view/frame/image_texture.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace ssao {

void ImageTexture::show(const std::shared_ptr<const Image>& img) {
    if (!img || img == shown_ || img->width <= 0 || img->height <= 0) return;
    if (!tex_ || tex_.width() != img->width || tex_.height() != img->height) {
        tex_ = gl::Texture2D(img->width, img->height, GL_RGBA8, "view.image");
        tex_.setFilter(GL_LINEAR); // drawn at the view's size, not the image's
    }
    std::vector<uint8_t> rgba(size_t(img->width) * img->height * 4, 255);
    for (size_t i = 0; i < size_t(img->width) * img->height; ++i) {
        const float v = std::clamp(img->data[i * size_t(img->channels)], 0.0f, 1.0f);
        const uint8_t g = uint8_t(v * 255.0f + 0.5f);
        rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = g;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(tex_.id(), 0, 0, 0, img->width, img->height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    shown_ = img;
}

} // namespace ssao
