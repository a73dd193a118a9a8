#include "measure/thumbnails.h"

#include "output/reference_report.h"
#include "util/error.h"
#include "util/files.h"

#include "../../shaders/include/view_colors.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace ssao {

namespace {

// Area average of `img` (any channels) down to `w` x `h`: each output pixel the mean of the
// source pixels whose centres fall in it (at least one).
Image shrink(const Image& img, int w, int h) {
    Image out{w, h, img.channels, std::vector<float>(size_t(w) * h * img.channels, 0.0f)};
    for (int y = 0; y < h; ++y) {
        const int y0 = y * img.height / h, y1 = std::max(y0 + 1, (y + 1) * img.height / h);
        for (int x = 0; x < w; ++x) {
            const int x0 = x * img.width / w, x1 = std::max(x0 + 1, (x + 1) * img.width / w);
            for (int c = 0; c < img.channels; ++c) {
                double sum = 0;
                for (int sy = y0; sy < y1; ++sy)
                    for (int sx = x0; sx < x1; ++sx)
                        sum += img.at(sx, sy, c);
                out.data[(size_t(y) * w + x) * img.channels + c] = float(sum / double((y1 - y0) * (x1 - x0)));
            }
        }
    }
    return out;
}

Image small(const Image& img) {
    const int w = std::min(kThumbnailWidth, img.width);
    const int h = std::max(1, int(double(img.height) * w / std::max(img.width, 1) + 0.5));
    return shrink(img, w, h);
}

std::string safe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
    return s;
}

void ensureDir(const std::string& dir) {
    makeOutputFolder(dir);
}

} // namespace

std::string thumbnailDir(const std::string& outDir, const std::string& scene, const std::string& viewpoint) {
    std::string name = safe(scene) + "__" + safe(viewpoint);
    if (name != scene + "__" + viewpoint) { // "a<b" and "a>b" would share "a_b": the exact names' hash tells them apart
        uint32_t h = 2166136261u;              // FNV-1a
        for (char c : scene + '\0' + viewpoint)
            h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
        char hex[16];
        std::snprintf(hex, sizeof hex, "_%08x", h);
        name += hex;
    }
    return (std::filesystem::path(outDir) / "thumbs" / name).string();
}
std::string aoThumbnail(const std::string& dir, size_t config) {
    return dir + "/c" + std::to_string(config) + ".ao.png";
}
std::string errorThumbnail(const std::string& dir, size_t config) {
    return dir + "/c" + std::to_string(config) + ".error.png";
}
std::string referenceThumbnail(const std::string& dir) {
    return dir + "/reference.png";
}

Image aoThumbnailImage(const Evaluation& e, const ReferenceImage& ref) {
    Image ao = e.test;
    for (size_t i = 0; i < ao.data.size(); ++i)
        if (!(ref.geometry[i] > 0.0f)) ao.data[i] = float(SSAO_SKY_GREY);
    return small(ao);
}

Image errorThumbnailImage(const Evaluation& e, const ReferenceImage& ref) {
    return small(errorHeatmap(e.error, ref.geometry));
}

Image referenceThumbnailImage(const ReferenceImage& ref) {
    return small(referencePreview(ref));
}

void writeThumbnails(const std::string& dir, size_t config, const Evaluation& e, const ReferenceImage& ref) {
    ensureDir(dir);
    writePng(aoThumbnailImage(e, ref), aoThumbnail(dir, config));
    writePng(errorThumbnailImage(e, ref), errorThumbnail(dir, config));
}

void writeReferenceThumbnail(const std::string& dir, const ReferenceImage& ref) {
    ensureDir(dir);
    writePng(referenceThumbnailImage(ref), referenceThumbnail(dir));
}

} // namespace ssao
