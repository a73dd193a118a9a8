// Encoded images are untrusted input. Before one is decoded, what its header says is checked: its
// pixels against a budget, and the work a decoder would do beyond the pixels - a progressive JPEG's
// scans (each a pass over the whole image), a PNG's compressed rows (inflated until they end, not
// until the header's size). The one check every image ssaolab decodes goes through: MASK textures
// (scene/load/mask_textures.h), --score images and cached references (base/image.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace ssao {

// Scans a JPEG may hold: 500, the limit libjpeg-turbo's own fuzz targets set (TJPARAM_SCANLIMIT).
// Ordinary progressive JPEGs hold about 10; each scan, empty or not, is a pass over the image.
constexpr int kMaxJpegScans = 500;

enum class ImageFormat { Png, Jpeg, Exr, Other };

struct ImageHeader {
    ImageFormat format = ImageFormat::Other;
    uint64_t width = 0, height = 0; // 0: no size could be read
    int scans = 0;                  // JPEG: its start-of-scan markers, every one in the stream
    uint64_t pixels() const;        // width x height, saturating
};

// The pixels decodes may produce in total, and what errors call it and the option that raises it.
struct ImageBudget {
    uint64_t pixels = uint64_t(64) << 20;   // SceneBudget::maskPixels' default
    uint64_t used = 0;                      // decoded already under the same budget
    std::string what = "decoded images";    // "MASK textures"
    std::string option = "--max-mask-mpix"; // the ssaolab option that raises it (millions of 2^20)
};

// What the header says, nothing decoded: PNG (IHDR), JPEG (its first frame header; every scan
// counted), OpenEXR (dataWindow), else whatever stb_image reads from the header of its formats.
ImageHeader readImageHeader(const unsigned char* data, size_t size);

// The header, checked before decoding: its pixels within what is left of the budget, a JPEG's scans
// at most kMaxJpegScans, a PNG's compressed rows inflating to no more than its header states (and a
// sixteenth of slack; one streaming pass, nothing kept). Throws one ssao::Error starting with `label`; a PNG, JPEG or EXR
// without a size in its header is refused, any other format is left to its decoder.
ImageHeader checkImageBudget(const unsigned char* data, size_t size, const ImageBudget& budget,
                             const std::string& label);

// The largest file an image within the budget is read from: 16 bytes a pixel (uncompressed RGBA
// float, the most an EXR stores) and 1 MiB of headers and tables.
size_t imageFileBytes(const ImageBudget& budget);

} // namespace ssao
