#include "output/frame_capture.h"

#include "util/error.h"

namespace ssao {

const CapturedBuffer* FrameCapture::find(const std::string& name) const {
    for (const CapturedBuffer& b : buffers)
        if (b.name == name) return &b;
    return nullptr;
}

const CapturedBuffer& FrameCapture::get(const std::string& name) const {
    if (const CapturedBuffer* b = find(name)) return *b;
    throw Error("no buffer named '" + name + "' in the frame");
}

} // namespace ssao
