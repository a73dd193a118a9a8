// What a parsed user header becomes for the GPU: the GLSL declarations ahead of the file's text,
// the uniform block's bytes, and the file's hash (user_header.h).
#include "techniques/user/user_header.h"

#include "techniques/user/user_parse.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace ssao {

std::string userParamsGlsl(const UserHeader& h, int binding) {
    if (binding < 0) throw Error("user technique: uniform binding " + std::to_string(binding) + " is negative");
    std::string s = "// The user technique's parameters (std140: a 4-byte scalar each; a bool is an int, 0 or 1).\n";
    s += "layout(std140, binding = " + std::to_string(binding) + ") uniform SsaoUserParams {\n";
    for (const auto& p : h.params)
        s += std::string(p.type == UserParam::Type::Float ? "    float " : "    int ") + p.name + ";\n";
    if (h.params.empty()) s += "    int ssao_no_params;\n"; // GLSL has no empty block
    s += "};\n";
    for (const auto& p : h.params)
        for (size_t i = 0; i < p.items.size(); ++i)
            s += "#define " + user::enumDefine(p.name, p.items[i]) + " " + std::to_string(i) + "\n";
    return s + "#line 1\n"; // the line after a #line N is line N (GLSL 3.30 and later)
}

std::vector<unsigned char> packUserParams(const UserHeader& h, const std::vector<double>& values) {
    if (values.size() != h.params.size())
        throw Error("user technique: " + std::to_string(h.params.size()) + " parameters, " +
                    std::to_string(values.size()) + " values");
    std::vector<unsigned char> out(std::max<size_t>(16, (4 * values.size() + 15) / 16 * 16), 0);
    for (size_t i = 0; i < values.size(); ++i) {
        const UserParam& p = h.params[i];
        const double v = values[i];
        const std::string what = "user parameter " + user::quoted(p.name) + ": value " + user::formatNumber(v);
        if (!std::isfinite(v)) throw Error(what + " is not finite");
        // A float parameter holds a float: compared at its precision (0.01 stored is 0.0099999998).
        const bool isFloat = p.type == UserParam::Type::Float;
        const bool below = isFloat ? float(v) < float(p.min) : v < p.min;
        const bool above = isFloat ? float(v) > float(p.max) : v > p.max;
        if (below || above || std::fabs(v) > 2147483647.0)
            throw Error(what + " is outside [" + user::formatNumber(p.min) + ", " + user::formatNumber(p.max) + "]");
        if (p.type == UserParam::Type::Float) {
            const float f = float(v);
            std::memcpy(&out[4 * i], &f, 4);
        } else {
            if (v != std::floor(v)) throw Error(what + " is not a whole number");
            const std::int32_t k = p.type == UserParam::Type::Bool ? (v != 0 ? 1 : 0) : std::int32_t(v);
            std::memcpy(&out[4 * i], &k, 4);
        }
    }
    return out;
}

std::string userTechniqueHash(const std::string& text) {
    std::uint64_t hash = 0xcbf29ce484222325ull; // FNV-1a 64: offset basis, then the prime per byte
    for (unsigned char c : text)
        hash = (hash ^ c) * 0x100000001b3ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

} // namespace ssao
