#include "util/file_kind.h"

#include <algorithm>

namespace ssao {

namespace {
struct Magic {
    const char* bytes;
    size_t size;
    size_t at; // offset of the signature
    const char* kind;
};

// The formats a user is likely to hand ssaolab by mistake: images, the other glTF containers, archives.
const Magic kMagics[] = {
    {"\x89PNG\r\n\x1a\n", 8, 0, "a PNG image"},
    {"\xff\xd8\xff", 3, 0, "a JPEG image"},
    {"glTF", 4, 0, "a GLB (binary glTF) scene"},
    {"v/1\x01", 4, 0, "an OpenEXR image"},
    {"GIF8", 4, 0, "a GIF image"},
    {"WEBP", 4, 8, "a WebP image"},
    {"\xabKTX 20\xbb", 8, 0, "a KTX2 texture"},
    {"DDS ", 4, 0, "a DDS texture"},
    {"#?RADIANCE", 10, 0, "a Radiance HDR image"},
    {"PK\x03\x04", 4, 0, "a zip archive"},
    {"\x1f\x8b", 2, 0, "a gzip archive"},
    {"%PDF", 4, 0, "a PDF document"},
    {"\177ELF", 4, 0, "a program (ELF)"},
    {"\xff\xfe", 2, 0, "UTF-16 text (JSON is read as UTF-8)"},
    {"\xfe\xff", 2, 0, "UTF-16 text (JSON is read as UTF-8)"},
};
} // namespace

std::string binaryFileKind(const std::string& bytes) {
    for (const Magic& m : kMagics)
        if (bytes.size() >= m.at + m.size && bytes.compare(m.at, m.size, m.bytes, m.size) == 0) return m.kind;
    // Text: no NUL and few control bytes besides whitespace in the first 4 KiB.
    const size_t n = std::min<size_t>(bytes.size(), 4096);
    size_t control = 0;
    for (size_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(bytes[i]);
        if (c == 0) return "binary data";
        control += (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != 0x1b) || c == 0x7f;
    }
    return control * 16 > n ? "binary data" : "";
}

} // namespace ssao
