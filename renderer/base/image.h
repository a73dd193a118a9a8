// CPU float images (rows top-to-bottom), EXR/PNG writers, and statistics; no GL (a texture is
// read into one by gl/readback.h).
#pragma once
#include "util/image_budget.h"

#include <functional>
#include <string>
#include <vector>

namespace ssao {

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> data; // row-major, top row first, interleaved channels

    float at(int x, int y, int c = 0) const { return data[(size_t(y) * width + x) * channels + c]; }
    Image channel(int c) const;
};

// The pixel of a `to`-wide image whose area holds the centre of pixel `p` of a `from`-wide one
// (same extent, e.g. a G-buffer pixel → its texel in half-resolution AO; odd sizes included).
inline int mapPixel(int p, int from, int to) {
    const long t = ((2L * p + 1) * to) / (2L * from);
    return int(t < 0 ? 0 : t >= to ? to - 1 : t);
}

// q-quantile (0..1) of `values` (reordered in place); NaN when empty.
float quantile(std::vector<float>& values, double q);

// OpenEXR, 32-bit float channels (1 = Y, 3 = RGB, 4 = RGBA). Throws ssao::Error.
void writeExr(const Image& img, const std::string& path);
// 8-bit PNG of `img` mapped through value * scale + offset, clamped to [0,1]; NaN → magenta.
void writePng(const Image& img, const std::string& path, float scale = 1.0f, float offset = 0.0f);
// The same PNG's bytes, for a page that embeds it.
std::string encodePng(const Image& img, float scale = 1.0f, float offset = 0.0f);

// Reading: the file through the file gate (a regular file, at most imageFileBytes(budget)), its
// header through checkImageBudget, then decoded from memory. Errors name the file as `what PATH`.
// An OpenEXR as RGBA (4 channels); anything else stb_image reads (PNG, PGM, JPEG) with its own
// channels, values in [0,1].
Image readExr(const std::string& path, const ImageBudget& budget = {}, const std::string& what = "image");
Image readPng(const std::string& path, const ImageBudget& budget = {}, const std::string& what = "image");
// readExr for an OpenEXR (by its magic number), else readPng.
Image readImage(const std::string& path, const ImageBudget& budget = {}, const std::string& what = "image");
// The same from bytes already read; `label` starts every error. `checkHeader`, if given, sees the
// header once it is within the budget and before anything is decoded (it throws to refuse it).
Image decodeImage(const std::string& bytes, const ImageBudget& budget, const std::string& label,
                  const std::function<void(const ImageHeader&)>& checkHeader = {});

struct Stats {
    long nonFinite = 0; // NaN or ±inf values over all pixels and channels
    long count = 0;     // finite values over masked pixels
    double min = 0, mean = 0, max = 0;
    double p05 = 0; // 5th percentile: the darkest 5 % of (AO) pixels are at or below it
    double p50 = 0; // median
};
// Statistics of channel 0 over pixels where mask (if given, at any resolution: sampled at the
// nearest pixel) has channel 0 > 0.
Stats stats(const Image& img, const Image* mask = nullptr);

} // namespace ssao
