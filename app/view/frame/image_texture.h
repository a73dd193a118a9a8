// An image the explorer shows that no pass of its renderer made (a web engine's AO frame, Split B
// of an engine point: front/engine_front.h): uploaded once per image as grey RGBA8, [0, 1].
#pragma once
#include "base/image.h"
#include "gl/resources.h"

#include <memory>

namespace ssao {

class ImageTexture {
  public:
    // Uploads channel 0 of `img` (top row first) unless it is the image uploaded last.
    void show(const std::shared_ptr<const Image>& img);
    // The texture (top row at v = 0), or null before an image was shown.
    const gl::Texture2D* texture() const { return tex_ ? &tex_ : nullptr; }

  private:
    gl::Texture2D tex_;
    std::shared_ptr<const Image> shown_;
};

} // namespace ssao
