#include "util/number_text.h"

#include <cmath>
#include <cstdio>

namespace ssao {

namespace {

const char* missingText(Missing m) {
    return m == Missing::EmptyCell ? "" : "–";
}

} // namespace

std::string numberText(double v, const char* fmt, Missing missing) {
    if (!std::isfinite(v) && missing != Missing::Spelled) return missingText(missing);
    char b[64];
    std::snprintf(b, sizeof b, fmt, v);
    return b;
}

std::string numberText(double v, const char* fmt, int digits, Missing missing) {
    if (!std::isfinite(v) && missing != Missing::Spelled) return missingText(missing);
    char b[64];
    std::snprintf(b, sizeof b, fmt, digits, v);
    return b;
}

} // namespace ssao
