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

ViewRadiusCheck checkViewRadius(const FrameCapture& frame) {
    const CapturedBuffer* depth = frame.find("gbuffer.depth");
    if (!depth || depth->values.channels != 1 || frame.height <= 0) return {};
    return checkViewRadius(depth->values.data.data(), depth->values.data.size(), frame.camera,
                           double(frame.width) / double(frame.height), frame.settings.ao, frame.radius.sceneDiagonal);
}

} // namespace ssao
