// GPU → CPU: a texture read into an Image (output/image.h), rows flipped from GL's bottom-up order.
#pragma once
#include "gl/resources.h"
#include "output/image.h"

namespace ssao {

// Reads `channels` channels of a texture (flipping GL's bottom-up rows).
Image readBack(const gl::Texture2D& tex, int channels);

} // namespace ssao
