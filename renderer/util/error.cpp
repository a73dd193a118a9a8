#include "util/error.h"

#include <cctype>
#include <cstdlib>

namespace ssao {

namespace {
// A cut at or before `at` that does not split a UTF-8 sequence.
size_t charBoundary(const std::string& s, size_t at) {
    while (at > 0 && at < s.size() && (static_cast<unsigned char>(s[at]) & 0xC0) == 0x80)
        --at;
    return at;
}
} // namespace

std::string oneLine(const std::string& message) {
    // A value echoed from input may be any length: the line keeps its start and its end, which
    // says what was expected, and how much was left out between them.
    constexpr size_t kMax = 600, kHead = 400, kTail = 160;
    std::string msg = message;
    if (msg.size() > kMax) {
        const size_t head = charBoundary(msg, kHead), tail = charBoundary(msg, msg.size() - kTail);
        msg = msg.substr(0, head) + " ... [" + std::to_string(tail - head) + " bytes left out] ... " + msg.substr(tail);
    }
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ' || msg.back() == '\r'))
        msg.pop_back();
    for (char& c : msg) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n' || c == '\r') c = ';';
        else if ((u < 0x20 && c != '\t') || u == 0x7f) c = '?';
    }
    return msg;
}

bool parseDecimal(const std::string& text, double& out) {
    if (text.empty()) return false;
    std::string lower;
    for (char c : text)
        lower += char(std::tolower((unsigned char)c));
    const std::string unsigned_ = lower[0] == '+' || lower[0] == '-' ? lower.substr(1) : lower;
    if (unsigned_ == "inf" || unsigned_ == "infinity" || unsigned_ == "nan") {
        out = std::strtod(text.c_str(), nullptr);
        return true;
    }
    // Digits, one optional point, an optional exponent: what strtod accepts minus hex and spaces.
    bool digits = false;
    size_t i = (text[0] == '+' || text[0] == '-') ? 1 : 0;
    for (; i < text.size() && std::isdigit((unsigned char)text[i]); ++i)
        digits = true;
    if (i < text.size() && text[i] == '.')
        for (++i; i < text.size() && std::isdigit((unsigned char)text[i]); ++i)
            digits = true;
    if (!digits) return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        bool expDigits = false;
        for (; i < text.size() && std::isdigit((unsigned char)text[i]); ++i)
            expDigits = true;
        if (!expDigits) return false;
    }
    if (i != text.size()) return false;
    out = std::strtod(text.c_str(), nullptr); // overflow gives ±inf, underflow 0: both reported by callers
    return true;
}

} // namespace ssao
