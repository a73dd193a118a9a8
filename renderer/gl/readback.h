// GPU → CPU: a texture read into an Image (base/image.h), rows flipped from GL's bottom-up order.
#pragma once
#include "base/image.h"
#include "gl/resources.h"

namespace ssao {

// Reads `channels` channels of a texture (flipping GL's bottom-up rows).
Image readBack(const gl::Texture2D& tex, int channels);

} // namespace ssao
