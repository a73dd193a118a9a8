#include "util/image_budget.h"

#include "util/error.h"

#include <stb_image.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <limits>

namespace ssao {

uint64_t ImageHeader::pixels() const {
    if (height && width > std::numeric_limits<uint64_t>::max() / height) return std::numeric_limits<uint64_t>::max();
    return width * height;
}

namespace {

uint32_t be32(const unsigned char* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}
uint32_t be16(const unsigned char* p) {
    return uint32_t(p[0]) << 8 | uint32_t(p[1]);
}
uint32_t le32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

const unsigned char kPngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
const unsigned char kExrMagic[4] = {0x76, 0x2F, 0x31, 0x01};

const char* formatName(ImageFormat f) {
    return f == ImageFormat::Png ? "PNG" : f == ImageFormat::Jpeg ? "JPEG" : f == ImageFormat::Exr ? "OpenEXR" : "image";
}

// JPEG (ITU T.81 annex B): marker segments with a 2-byte length, entropy-coded data after each
// start of scan up to the next marker that is neither a stuffed 0xFF00 nor a restart. The walk goes
// at least as far as stb_image's decoder would, so no scan it decodes goes uncounted.
ImageHeader jpegHeader(const unsigned char* d, size_t n) {
    ImageHeader h;
    h.format = ImageFormat::Jpeg;
    bool frame = false;
    size_t i = 2;
    while (i + 1 < n && d[i] == 0xFF) {
        while (i + 1 < n && d[i + 1] == 0xFF) // fill bytes
            ++i;
        if (i + 1 >= n) break;
        const unsigned m = d[i + 1];
        i += 2;
        if (m == 0xD9) break;                                  // end of image
        if ((m >= 0xD0 && m <= 0xD7) || m == 0x01) continue; // no length: restart, TEM
        if (i + 2 > n) break;
        const size_t len = be16(d + i);
        if (len < 2 || len > n - i) break; // runs past the file: the decoder fails there
        const bool sof = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
        if (sof && !frame && len >= 7) {
            h.height = be16(d + i + 3), h.width = be16(d + i + 5);
            frame = true;
        }
        i += len;
        if (m != 0xDA) continue;
        ++h.scans;
        while (i + 1 < n && !(d[i] == 0xFF && d[i + 1] != 0x00 && !(d[i + 1] >= 0xD0 && d[i + 1] <= 0xD7)))
            ++i;
    }
    return h;
}

// OpenEXR: magic, version and flags, then attributes (name, type, 4-byte size, value) up to an
// empty name; the pixels are the dataWindow's (box2i: xMin, yMin, xMax, yMax, inclusive).
ImageHeader exrHeader(const unsigned char* d, size_t n) {
    ImageHeader h;
    h.format = ImageFormat::Exr;
    if (n < 8 || (le32(d + 4) & 0x1800)) return h; // several parts or deep data: not read
    size_t i = 8;
    auto text = [&](std::string& out) {
        const unsigned char* end = static_cast<const unsigned char*>(std::memchr(d + i, 0, std::min<size_t>(n - i, 256)));
        if (!end) return false;
        out.assign(reinterpret_cast<const char*>(d + i), size_t(end - (d + i)));
        i = size_t(end - d) + 1;
        return true;
    };
    std::string name, type;
    while (i < n && d[i] != 0) {
        if (!text(name) || i >= n || !text(type) || n - i < 4) break;
        const size_t size = le32(d + i);
        i += 4;
        if (size > n - i) break;
        if (name == "dataWindow" && type == "box2i" && size == 16) {
            const int64_t x0 = int32_t(le32(d + i)), y0 = int32_t(le32(d + i + 4));
            const int64_t x1 = int32_t(le32(d + i + 8)), y1 = int32_t(le32(d + i + 12));
            if (x1 >= x0 && y1 >= y0) h.width = uint64_t(x1 - x0 + 1), h.height = uint64_t(y1 - y0 + 1);
        }
        i += size;
    }
    return h;
}

// Bytes of the filtered rows (a filter byte each) a PNG of this header inflates to; Adam7: its
// seven passes'. 0 for a colour type or depth that is not PNG's.
uint64_t pngRawBytes(const ImageHeader& h, int depth, int colour, bool interlaced) {
    const int channels = colour == 0 ? 1 : colour == 2 ? 3 : colour == 3 ? 1 : colour == 4 ? 2 : colour == 6 ? 4 : 0;
    const uint64_t bits = uint64_t(channels) * uint64_t(depth > 0 && depth <= 16 ? depth : 0);
    auto rows = [&](uint64_t w, uint64_t hh) { return w && hh ? hh * (1 + (w * bits + 7) / 8) : 0; };
    if (!interlaced) return rows(h.width, h.height);
    static const int x0[7] = {0, 4, 0, 2, 0, 1, 0}, y0[7] = {0, 0, 4, 0, 2, 0, 1};
    static const int dx[7] = {8, 8, 4, 4, 2, 2, 1}, dy[7] = {8, 8, 8, 4, 4, 2, 2};
    uint64_t total = 0;
    for (int p = 0; p < 7; ++p)
        total += rows((h.width + uint64_t(dx[p] - 1 - x0[p])) / uint64_t(dx[p]),
                      (h.height + uint64_t(dy[p] - 1 - y0[p])) / uint64_t(dy[p]));
    return total;
}

struct Inflater {
    z_stream z{};
    bool open = false;
    ~Inflater() {
        if (open) inflateEnd(&z);
    }
};

// Inflates every IDAT chunk in one pass into a 64 KiB scratch buffer, counting: stb_image inflates
// until the stream ends, so a 1 x 1 header over 3 GiB of zeros (3 MB compressed) takes 2 GiB.
void checkPngInflation(const unsigned char* d, size_t n, const ImageHeader& h, const std::string& label) {
    const uint64_t rows = pngRawBytes(h, d[24], d[25], d[28] == 1);
    if (rows == 0) return; // a colour type or depth no decoder accepts
    const uint64_t limit = rows + rows / 16 + 4096; // slack for encoders that pad: decoders ignore the excess
    Inflater inf;
    bool apple = false; // CgBI: Apple's PNGs hold raw deflate, no zlib header
    uint64_t total = 0;
    unsigned char out[1 << 16];
    for (size_t at = 8; at + 12 <= n;) {
        const size_t len = be32(d + at);
        if (len > n - at - 12) break; // runs past the file: the decoder fails there
        const unsigned char* type = d + at + 4;
        if (std::memcmp(type, "CgBI", 4) == 0) apple = true;
        if (std::memcmp(type, "IEND", 4) == 0) break;
        if (std::memcmp(type, "IDAT", 4) == 0) {
            if (!inf.open) {
                if (inflateInit2(&inf.z, apple ? -15 : 15) != Z_OK) throw Error(label + ": cannot inflate it (zlib)");
                inf.open = true;
                inflateValidate(&inf.z, 0); // stb_image ignores the Adler-32 check value
            }
            inf.z.next_in = const_cast<unsigned char*>(d + at + 8);
            inf.z.avail_in = uInt(len);
            int rc = Z_OK;
            while (inf.z.avail_in > 0 && rc == Z_OK) {
                inf.z.next_out = out, inf.z.avail_out = sizeof out;
                rc = inflate(&inf.z, Z_NO_FLUSH);
                total += sizeof out - inf.z.avail_out;
                if (total > limit)
                    throw Error(label + " inflates to more than the " + std::to_string(h.width) + "x" +
                                std::to_string(h.height) + " pixels its header states (a decompression bomb)");
            }
            if (rc == Z_STREAM_END) break;
            if (rc != Z_OK && rc != Z_BUF_ERROR)
                throw Error(label + " is not a PNG that can be read (its compressed pixels are corrupt)");
        }
        at += 12 + len;
    }
}

} // namespace

ImageHeader readImageHeader(const unsigned char* data, size_t size) {
    if (size >= 29 && std::equal(kPngMagic, kPngMagic + 8, data) && std::memcmp(data + 12, "IHDR", 4) == 0) {
        ImageHeader h;
        h.format = ImageFormat::Png;
        h.width = be32(data + 16), h.height = be32(data + 20);
        return h;
    }
    if (size >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF) return jpegHeader(data, size);
    if (size >= 4 && std::equal(kExrMagic, kExrMagic + 4, data)) return exrHeader(data, size);
    ImageHeader h; // stb_image's other formats (PNM, BMP, TGA, ...): their headers, as stb reads them
    int w = 0, hh = 0, comp = 0;
    if (size <= size_t(std::numeric_limits<int>::max()) && stbi_info_from_memory(data, int(size), &w, &hh, &comp) &&
        w > 0 && hh > 0)
        h.width = uint64_t(w), h.height = uint64_t(hh);
    return h;
}

ImageHeader checkImageBudget(const unsigned char* data, size_t size, const ImageBudget& budget,
                             const std::string& label) {
    const ImageHeader h = readImageHeader(data, size);
    if (h.format != ImageFormat::Other && h.pixels() == 0)
        throw Error(label + " is not " + (h.format == ImageFormat::Exr ? "an " : "a ") + formatName(h.format) +
                    " that can be read (no size in its header)");
    const uint64_t left = budget.pixels - std::min(budget.used, budget.pixels);
    if (h.pixels() > left)
        throw Error(label + " is " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                    " pixels: past the budget of " + std::to_string(budget.pixels >> 20) + " M pixels for " +
                    budget.what +
                    (budget.used ? " (" + std::to_string(budget.used >> 20) + " M already decoded)" : std::string()) +
                    (budget.option.empty() ? std::string() : " (raise it with ssaolab " + budget.option + " N)"));
    if (h.format == ImageFormat::Jpeg && h.scans > kMaxJpegScans)
        throw Error(label + " holds " + std::to_string(h.scans) + " scans, past the limit of " +
                    std::to_string(kMaxJpegScans) + " a JPEG may hold (each is a pass over the whole image; "
                    "ordinary progressive JPEGs hold about 10)");
    if (h.format == ImageFormat::Png) checkPngInflation(data, size, h, label);
    return h;
}

size_t imageFileBytes(const ImageBudget& budget) {
    const uint64_t cap = uint64_t(std::numeric_limits<size_t>::max() / 2);
    return size_t(std::min(cap, budget.pixels > cap / 16 ? cap : budget.pixels * 16 + (uint64_t(1) << 20)));
}

} // namespace ssao
