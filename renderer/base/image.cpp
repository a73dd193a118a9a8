#include "base/image.h"

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace ssao {

Image Image::channel(int c) const {
    Image out{width, height, 1, std::vector<float>(size_t(width) * height)};
    for (size_t i = 0; i < out.data.size(); ++i)
        out.data[i] = data[i * channels + c];
    return out;
}

namespace {
// The EXR file's bytes (as tinyexr's SaveEXR lays them out: fp32, (A)BGR channel order, ZIP above
// 16x16), made in memory: no file is written but the destination, atomically.
std::string encodeExr(const Image& img) {
    const int c = img.channels, w = img.width, h = img.height;
    if (c != 1 && c != 3 && c != 4) throw Error("EXR: unsupported channel count " + std::to_string(c));
    const size_t n = size_t(w) * size_t(h), nc = static_cast<size_t>(c);
    std::vector<std::vector<float>> planes(nc, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < c; ++k)
            planes[size_t(k)][i] = img.data[size_t(c) * i + size_t(k)];
    static const char* names1[] = {"A"};
    static const char* names3[] = {"B", "G", "R"};
    static const char* names4[] = {"A", "B", "G", "R"};
    const char** names = c == 1 ? names1 : c == 3 ? names3 : names4;
    std::vector<float*> ptrs(nc);
    std::vector<EXRChannelInfo> channels(nc);
    std::vector<int> types(nc, TINYEXR_PIXELTYPE_FLOAT);
    for (int k = 0; k < c; ++k) {
        const int plane = c == 1 ? 0 : c == 3 ? 2 - k : (k == 0 ? 3 : 3 - k); // (A)BGR from RGB(A)
        ptrs[size_t(k)] = planes[size_t(plane)].data();
        std::memset(channels[size_t(k)].name, 0, sizeof channels[size_t(k)].name);
        std::strncpy(channels[size_t(k)].name, names[k], sizeof channels[size_t(k)].name - 1);
    }
    EXRHeader header;
    InitEXRHeader(&header);
    header.compression_type = (w < 16 && h < 16) ? TINYEXR_COMPRESSIONTYPE_NONE : TINYEXR_COMPRESSIONTYPE_ZIP;
    header.num_channels = c;
    header.channels = channels.data();
    header.pixel_types = types.data();
    header.requested_pixel_types = types.data();
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = c;
    image.images = reinterpret_cast<unsigned char**>(ptrs.data());
    image.width = w;
    image.height = h;
    unsigned char* mem = nullptr;
    const char* err = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &mem, &err);
    if (size == 0 || !mem) {
        const std::string msg = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        throw Error("EXR encoding failed: " + msg);
    }
    std::string bytes(reinterpret_cast<const char*>(mem), size);
    std::free(mem);
    return bytes;
}
} // namespace

void writeExr(const Image& img, const std::string& path) {
    // fp32 keeps NaN/inf and full precision; the bytes go to disk through the atomic writer.
    std::string bytes;
    try {
        bytes = encodeExr(img);
    } catch (const Error& e) {
        throw Error("cannot write " + path + ": " + e.what());
    }
    writeFileAtomically(path, bytes);
}

namespace {
// An OpenEXR from memory, as RGBA float.
Image decodeExr(const std::string& bytes, const std::string& label) {
    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    if (LoadEXRFromMemory(&rgba, &w, &h, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), &err) !=
        TINYEXR_SUCCESS) {
        const std::string msg = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        throw Error("cannot read " + label + ": " + msg);
    }
    Image img{w, h, 4, std::vector<float>(rgba, rgba + size_t(w) * size_t(h) * 4)};
    std::free(rgba);
    return img;
}

// Anything stb_image reads, from memory, with its own channels mapped to [0,1].
Image decodeStb(const std::string& bytes, const std::string& label) {
    if (bytes.size() > size_t(std::numeric_limits<int>::max())) throw Error("cannot read " + label + ": over 2 GiB");
    int w = 0, h = 0, c = 0;
    unsigned char* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w,
                                              &h, &c, 0);
    if (!px)
        throw Error("cannot read " + label + ": " +
                    (stbi_failure_reason() ? stbi_failure_reason() : "not an image stb_image reads"));
    Image img{w, h, c, std::vector<float>(size_t(w) * size_t(h) * size_t(c))};
    for (size_t i = 0; i < img.data.size(); ++i)
        img.data[i] = float(px[i]) / 255.0f;
    stbi_image_free(px);
    return img;
}

std::string readImageFile(const std::string& path, const ImageBudget& budget, const std::string& what) {
    return readRegularFile(path, what, imageFileBytes(budget));
}
} // namespace

Image decodeImage(const std::string& bytes, const ImageBudget& budget, const std::string& label,
                  const std::function<void(const ImageHeader&)>& checkHeader) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const ImageHeader h = checkImageBudget(data, bytes.size(), budget, label);
    if (h.pixels() == 0) throw Error("cannot read " + label + ": not a PNG, PGM, JPEG or OpenEXR image");
    if (checkHeader) checkHeader(h);
    return h.format == ImageFormat::Exr ? decodeExr(bytes, label) : decodeStb(bytes, label);
}

Image readExr(const std::string& path, const ImageBudget& budget, const std::string& what) {
    const std::string label = what + " " + path;
    const std::string bytes = readImageFile(path, budget, what);
    if (readImageHeader(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()).format != ImageFormat::Exr)
        throw Error("cannot read " + label + ": not an OpenEXR file");
    return decodeImage(bytes, budget, label);
}

Image readImage(const std::string& path, const ImageBudget& budget, const std::string& what) {
    return decodeImage(readImageFile(path, budget, what), budget, what + " " + path);
}

std::string encodePng(const Image& img, float scale, float offset) {
    const int outC = img.channels == 1 ? 1 : img.channels >= 3 ? 3 : img.channels;
    std::vector<unsigned char> px(size_t(img.width) * img.height * outC);
    for (size_t p = 0; p < size_t(img.width) * img.height; ++p) {
        bool bad = false;
        for (int c = 0; c < outC; ++c)
            bad |= !std::isfinite(img.data[p * img.channels + c]);
        for (int c = 0; c < outC; ++c) {
            float v = img.data[p * img.channels + c] * scale + offset;
            if (bad) v = (outC == 1) ? 1.0f : (c == 1 ? 0.0f : 1.0f); // magenta flags NaN/inf
            px[p * outC + c] = (unsigned char)std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f);
        }
    }
    std::string bytes; // encoded in memory: stb's file writer ignores failed writes
    auto append = [](void* ctx, void* data, int size) {
        static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, img.width, img.height, outC, px.data(), img.width * outC))
        throw Error("PNG encoding failed");
    return bytes;
}

void writePng(const Image& img, const std::string& path, float scale, float offset) {
    std::string bytes;
    try {
        bytes = encodePng(img, scale, offset);
    } catch (const Error& e) {
        throw Error("cannot write " + path + ": " + e.what());
    }
    writeFileAtomically(path, bytes);
}

Image readPng(const std::string& path, const ImageBudget& budget, const std::string& what) {
    const std::string label = what + " " + path;
    const std::string bytes = readImageFile(path, budget, what);
    if (readImageHeader(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()).format == ImageFormat::Exr)
        throw Error("cannot read " + label + ": an OpenEXR file, not an image stb_image reads");
    return decodeImage(bytes, budget, label);
}

float quantile(std::vector<float>& v, double q) {
    if (v.empty()) return NAN;
    const size_t k = size_t(std::clamp(q, 0.0, 1.0) * double(v.size() - 1) + 0.5);
    std::nth_element(v.begin(), v.begin() + ptrdiff_t(k), v.end());
    return v[k];
}

Stats stats(const Image& img, const Image* mask) {
    Stats s;
    double sum = 0;
    s.min = std::numeric_limits<double>::infinity();
    s.max = -s.min;
    std::vector<float> values;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const size_t p = size_t(y) * size_t(img.width) + size_t(x);
            for (int c = 0; c < img.channels; ++c)
                if (!std::isfinite(img.data[p * img.channels + c])) ++s.nonFinite;
            if (mask && !(mask->at(mapPixel(x, img.width, mask->width),
                                   mapPixel(y, img.height, mask->height)) > 0.0f))
                continue;
            const float v = img.data[p * img.channels];
            if (!std::isfinite(v)) continue;
            ++s.count;
            sum += v;
            s.min = std::min(s.min, double(v));
            s.max = std::max(s.max, double(v));
            values.push_back(v);
        }
    if (s.count) {
        s.mean = sum / double(s.count);
        s.p05 = quantile(values, 0.05);
        s.p50 = quantile(values, 0.5);
    } else {
        s.min = s.max = 0;
    }
    return s;
}

} // namespace ssao
