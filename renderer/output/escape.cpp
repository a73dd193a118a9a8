#include "output/escape.h"

namespace ssao {

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
