#include "output/reference_report.h"

#include "../../shaders/include/view_colors.h"

#include <filesystem>

namespace ssao {

ReferenceSettings referenceSettingsFor(const RadiusInfo& radius, int rays, ReferenceVariant variant) {
    ReferenceSettings s;
    s.radius = radius.world;
    s.samples = rays;
    s.variant = variant;
    return s;
}

Image referencePreview(const ReferenceImage& ref) {
    Image img{ref.width, ref.height, 1, ref.ao};
    // The sky as ao.denoised.png draws it: white sky (open AO) hid every silhouette against it.
    for (size_t i = 0; i < img.data.size(); ++i)
        if (!(ref.geometry[i] > 0.0f)) img.data[i] = float(SSAO_SKY_GREY);
    return img;
}

nlohmann::json writeReferenceOutputs(const FrameCapture& c, const ReferenceImage& ref, const ReferenceSettings& s,
                                     const std::string& dir) {
    auto path = [&](const std::string& f) { return (std::filesystem::path(dir) / f).string(); };
    const Image& ao = c.get("ao.denoised").values;
    const Image& raw = c.get("ao.raw").values;
    const Evaluation e = evaluate(ao, ref);
    const Evaluation eRaw = evaluate(raw, ref);

    const Image refImg{ref.width, ref.height, 1, ref.ao};
    writeExr(refImg, path("ao_reference.exr"));
    writePng(referencePreview(ref), path("ao_reference.png"));
    writeExr(Image{ref.width, ref.height, 1, ref.stdErr}, path("ao_reference_stderr.exr"));
    writeExr(e.error, path("error.exr"));
    writePng(errorHeatmap(e.error, ref.geometry), path("error.png"));
    nlohmann::json j;
    j["error"] = metricsJson(e.metrics, ref, s);
    j["error"]["files"] = {"ao_reference.exr", "ao_reference.png", "ao_reference_stderr.exr", "error.exr",
                           "error.png"};
    j["error"]["heatmap"] = "error.png: blue = too dark, red = too bright, white = 0, saturates at 0.25";
    j["error_raw"] = metricsJson(eRaw.metrics, ref, s);
    return j;
}

} // namespace ssao
