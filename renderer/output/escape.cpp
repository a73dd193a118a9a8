#include "output/escape.h"

#include <cstdint>
#include <cstdio>
#include <utility>

namespace ssao {

namespace {

// The code point of the UTF-8 sequence at s[i] and its length; an invalid, overlong or truncated
// sequence is U+FFFD of one byte.
std::pair<uint32_t, size_t> utf8At(const std::string& s, size_t i) {
    const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = b(i);
    if (c < 0x80) return {c, 1};
    const size_t n = c >= 0xf0 && c <= 0xf4 ? 4 : c >= 0xe0 ? (c < 0xf0 ? 3 : 0) : c >= 0xc2 ? 2 : 0;
    if (n == 0 || i + n > s.size()) return {0xfffd, 1};
    uint32_t cp = c & (0xff >> (n + 1));
    for (size_t k = 1; k < n; ++k) {
        if ((b(i + k) & 0xc0) != 0x80) return {0xfffd, 1};
        cp = (cp << 6) | (b(i + k) & 0x3f);
    }
    const uint32_t least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < least[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {0xfffd, 1};
    return {cp, n};
}

void appendU(std::string& o, uint32_t unit) {
    char b[8];
    std::snprintf(b, sizeof b, "\\u%04X", unsigned(unit));
    o += b;
}

} // namespace

std::string jsString(const std::string& s) {
    std::string o = "\"";
    for (size_t i = 0; i < s.size();) {
        const auto [cp, n] = utf8At(s, i);
        i += n;
        if (cp == '"' || cp == '\\') {
            o += '\\';
            o += char(cp);
        } else if (cp >= 0x20 && cp < 0x7f && cp != '<' && cp != '>') {
            o += char(cp);
        } else if (cp < 0x10000) {
            appendU(o, cp);
        } else { // a UTF-16 surrogate pair
            appendU(o, 0xd800 + ((cp - 0x10000) >> 10));
            appendU(o, 0xdc00 + ((cp - 0x10000) & 0x3ff));
        }
    }
    return o + "\"";
}

std::string jsCommentText(const std::string& s) {
    std::string o = s;
    for (char& c : o)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return o;
}

std::string htmlText(const std::string& s) {
    std::string o;
    o.reserve(s.size());
    for (char c : s) {
        switch (c) {
        case '&': o += "&amp;"; break;
        case '<': o += "&lt;"; break;
        case '>': o += "&gt;"; break;
        case '"': o += "&quot;"; break;
        case '\'': o += "&#39;"; break;
        default: o += c;
        }
    }
    return o;
}

std::string htmlAttr(const std::string& s) {
    return htmlText(s);
}

std::string markdownCell(const std::string& s) {
    std::string o;
    o.reserve(s.size());
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        switch (c) {
        case '&': o += "&amp;"; break;
        case '<': o += "&lt;"; break;
        case '>': o += "&gt;"; break;
        case '\r':
            if (i + 1 < s.size() && s[i + 1] == '\n') ++i; // CRLF is one line break
            o += ' ';
            break;
        case '\n': o += ' '; break;
        case '|': case '\\': case '`': case '*': case '_': case '[': case ']':
            o += '\\';
            o += c;
            break;
        default: o += c;
        }
    }
    return o;
}

std::string csvField(const std::string& s) {
    std::string v = s;
    if (!v.empty() && (v[0] == '=' || v[0] == '+' || v[0] == '-' || v[0] == '@' || v[0] == '\t' || v[0] == '\r'))
        v.insert(v.begin(), '\'');
    if (v.find_first_of(",\"\r\n") == std::string::npos) return v;
    std::string q = "\"";
    for (char c : v)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

} // namespace ssao
