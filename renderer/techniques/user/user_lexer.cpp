#include "techniques/user/user_parse.h"

#include "util/error.h"

#include <cctype>
#include <cstdio>

namespace ssao::user {

namespace {
bool digit(char c) { return c >= '0' && c <= '9'; }
bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool printable(char c) { return c >= 0x20 && c <= 0x7e; }

std::string byteHex(char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02x", unsigned(static_cast<unsigned char>(c)));
    return buf;
}
} // namespace

void Where::fail(int line, const std::string& message) const {
    throw Error(oneLine(file + ":" + std::to_string(line) + ": " + message));
}

std::string formatNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

std::string quoted(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size() && i < 40; ++i)
        out += s[i] == '\0' ? std::string("\\0") : printable(s[i]) ? std::string(1, s[i]) : std::string("?");
    return "'" + out + (s.size() > 40 ? "...'" : "'");
}

const Token& Lexer::peek() {
    if (!hasPeeked_) peeked_ = lex(), hasPeeked_ = true;
    return peeked_;
}

Token Lexer::next() {
    peek();
    hasPeeked_ = false;
    return peeked_;
}

void Lexer::skipBlanks() {
    while (pos_ < end_) {
        const char c = t_[pos_];
        if (c == '\n') {
            ++line_, ++pos_;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
            ++pos_;
        } else if (c == '/' && pos_ + 1 < end_ && t_[pos_ + 1] == '/') {
            while (pos_ < end_ && t_[pos_] != '\n') ++pos_; // a comment's bytes are never tokens
        } else {
            return;
        }
    }
}

Token Lexer::lex() {
    skipBlanks();
    Token t;
    t.line = line_;
    if (pos_ >= end_) return t;
    const char c = t_[pos_];
    const bool fraction = pos_ + 1 < end_ && t_[pos_ + 1] == '.' && pos_ + 2 < end_ && digit(t_[pos_ + 2]);
    if (digit(c) || (c == '.' && pos_ + 1 < end_ && digit(t_[pos_ + 1])) ||
        (c == '-' && pos_ + 1 < end_ && (digit(t_[pos_ + 1]) || fraction)))
        return number();
    if (identStart(c)) {
        const size_t from = pos_;
        while (pos_ < end_ && identChar(t_[pos_])) ++pos_;
        t.kind = Token::Kind::Ident;
        t.text = t_.substr(from, pos_ - from);
        return t;
    }
    if (c == '"') return string();
    if (!printable(c))
        where_.fail(line_, "byte " + byteHex(c) +
                               " is not allowed in the header: printable ASCII outside strings and comments");
    t.kind = Token::Kind::Punct;
    t.text = std::string(1, c);
    ++pos_;
    return t;
}

// -?(digits[.digits]|.digits)([eE][+-]?digits)?[fF]? and nothing glued to it.
Token Lexer::number() {
    Token t;
    t.kind = Token::Kind::Number;
    t.line = line_;
    const size_t from = pos_;
    bool ok = true, whole = true;
    if (t_[pos_] == '-') ++pos_;
    while (pos_ < end_ && digit(t_[pos_])) ++pos_;
    if (pos_ < end_ && t_[pos_] == '.') {
        whole = false, ++pos_;
        while (pos_ < end_ && digit(t_[pos_])) ++pos_;
    }
    if (pos_ < end_ && (t_[pos_] == 'e' || t_[pos_] == 'E')) {
        whole = false, ++pos_;
        if (pos_ < end_ && (t_[pos_] == '+' || t_[pos_] == '-')) ++pos_;
        ok = pos_ < end_ && digit(t_[pos_]);
        while (pos_ < end_ && digit(t_[pos_])) ++pos_;
    }
    const size_t digitsEnd = pos_;
    if (pos_ < end_ && (t_[pos_] == 'f' || t_[pos_] == 'F')) whole = false, ++pos_;
    while (pos_ < end_ && (identChar(t_[pos_]) || t_[pos_] == '.')) ok = false, ++pos_;
    t.text = t_.substr(from, pos_ - from);
    if (!ok || !parseDecimal(t_.substr(from, digitsEnd - from), t.number))
        where_.fail(t.line, "malformed number " + quoted(t.text) +
                                ": decimal digits, an optional point, exponent and f suffix");
    t.whole = whole;
    return t;
}

// "..." on one line; escapes \" \\ \0. A bad escape or byte is kept as the token's problem: it
// is an error only where the string is used (ReShade's ignored annotations may hold anything).
Token Lexer::string() {
    Token t;
    t.kind = Token::Kind::String;
    t.line = line_;
    ++pos_;
    auto setProblem = [&](const std::string& p) {
        if (t.problem.empty()) t.problem = p;
    };
    for (;;) {
        if (pos_ >= end_ || t_[pos_] == '\n' || t_[pos_] == '\r')
            where_.fail(t.line, "unterminated string: a string closes with \" on its own line");
        const char c = t_[pos_];
        if (c == '"') {
            ++pos_;
            return t;
        }
        if (c == '\\') {
            const char e = pos_ + 1 < end_ ? t_[pos_ + 1] : '\n';
            if (e == '\n' || e == '\r') {
                ++pos_;
                continue; // reported as unterminated above
            }
            if (e == '"' || e == '\\') t.text += e;
            else if (e == '0') t.text += '\0';
            else
                setProblem("unknown escape \\" + (printable(e) ? std::string(1, e) : byteHex(e)) +
                           " in a string: the escapes are \\\" \\\\ and \\0 (in ui_items)");
            pos_ += 2;
            continue;
        }
        if (!printable(c))
            setProblem("byte " + byteHex(c) + " in a string: only printable ASCII (strings reach the UI, " +
                       "presets and reports)");
        else
            t.text += c;
        ++pos_;
    }
}

} // namespace ssao::user
