#include "output/image.h"

#include "util/atomic_file.h"
#include "util/error.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace ssao {

Image Image::channel(int c) const {
    Image out{width, height, 1, std::vector<float>(size_t(width) * height)};
    for (size_t i = 0; i < out.data.size(); ++i)
        out.data[i] = data[i * channels + c];
    return out;
}

void writeExr(const Image& img, const std::string& path) {
    const char* err = nullptr;
    // tinyexr wants 1, 3 or 4 channels; fp32 keeps NaN/inf and full precision. It writes to a file
    // only, so the file is made beside the destination and read back whole: a write that a full disk
    // cut short fails here (or at the atomic rename) instead of leaving a broken EXR.
    const std::string staged = path + ".exr-staged";
    int rc = SaveEXR(img.data.data(), img.width, img.height, img.channels, 0, staged.c_str(), &err);
    if (rc != TINYEXR_SUCCESS) {
        std::string msg = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        std::remove(staged.c_str());
        throw Error("cannot write " + path + ": " + msg);
    }
    std::string bytes;
    {
        std::ifstream in(staged, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::remove(staged.c_str());
    EXRVersion version;
    if (bytes.empty() ||
        ParseEXRVersionFromMemory(&version, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()) !=
            TINYEXR_SUCCESS)
        throw Error("cannot write " + path + ": the EXR came out truncated (disk full?)");
    writeFileAtomically(path, bytes);
}

Image readExr(const std::string& path) {
    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    if (LoadEXR(&rgba, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        std::string msg = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        throw Error("cannot read " + path + ": " + msg);
    }
    Image img{w, h, 4, std::vector<float>(rgba, rgba + size_t(w) * h * 4)};
    std::free(rgba);
    return img;
}

void writePng(const Image& img, const std::string& path, float scale, float offset) {
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
        throw Error("cannot write " + path + ": PNG encoding failed");
    writeFileAtomically(path, bytes);
}

Image readPng(const std::string& path) {
    int w = 0, h = 0, c = 0;
    unsigned char* px = stbi_load(path.c_str(), &w, &h, &c, 0);
    if (!px) throw Error("cannot read " + path);
    Image img{w, h, c, std::vector<float>(size_t(w) * h * c)};
    for (size_t i = 0; i < img.data.size(); ++i)
        img.data[i] = float(px[i]) / 255.0f;
    stbi_image_free(px);
    return img;
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
