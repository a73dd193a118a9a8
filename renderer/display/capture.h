// The GL side of the reports: reads a rendered frame's buffers back into a FrameCapture
// (output/frame_capture.h) and paints each buffer's preview through the app's one display mapping
// (view_painter.h), so the files and metrics written from it match what the app shows.
#pragma once
#include "display/display_range.h"
#include "output/frame_capture.h"
#include "renderer.h"

namespace ssao {

// Every buffer of chain A and the shared ones (Renderer::buffers), with previews painted in
// `style` when `previews` is true.
FrameCapture captureFrame(Renderer& r, const ViewStyle& style = {}, bool previews = true);

} // namespace ssao
