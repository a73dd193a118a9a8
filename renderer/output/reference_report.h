// Writes a frame's judgement against the reference: ao_reference.exr/.png, the reference's
// per-pixel standard error, the signed error (error.exr, heat map error.png) and the metrics.
// No GL: the frame is a capture (output/frame_capture.h).
#pragma once
#include "metrics/evaluate.h"
#include "output/frame_capture.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

// The reference settings a frame is judged with: R = the AO's world radius (for
// ao.radius_mode=screen, the world radius at the centre of the view).
ReferenceSettings referenceSettingsFor(const RadiusInfo& radius, int rays, ReferenceVariant variant);

// The reference as a preview (ao_reference.png, bench thumbnails): AO in [0,1], the sky in the
// views' sky grey (SSAO_SKY_GREY), like ao.denoised.png.
Image referencePreview(const ReferenceImage& ref);

// Evaluates ao.denoised (and ao.raw) of the frame; writes the files into `dir`; returns
// {"error": metrics of ao.denoised, "error_raw": metrics of ao.raw}.
nlohmann::json writeReferenceOutputs(const FrameCapture& c, const ReferenceImage& ref, const ReferenceSettings& s,
                                     const std::string& dir);

} // namespace ssao
