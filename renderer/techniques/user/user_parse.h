// The pieces of user_header.cpp's parser (internal to techniques/user/): the header's tokens, the
// raw declaration of one parameter and the checks that turn it into a UserParam.
#pragma once
#include "techniques/user/user_header.h"

#include <string>
#include <vector>

namespace ssao::user {

// Throws the one-line ssao::Error "FILE:LINE: message".
struct Where {
    std::string file;
    [[noreturn]] void fail(int line, const std::string& message) const;
};

struct Token {
    enum class Kind { End, Ident, Number, String, Punct } kind = Kind::End;
    std::string text; // Ident: the name; Number: as written; String: decoded (\0 as a NUL); Punct: the char
    double number = 0;
    bool whole = false;  // a Number written with no point, exponent or suffix
    std::string problem; // a String that may not reach the UI: why (raised only where it is used)
    int line = 0;

    bool is(char punct) const { return kind == Kind::Punct && text.size() == 1 && text[0] == punct; }
    bool isWord(const char* w) const { return kind == Kind::Ident && text == w; }
};

// The tokens of text[begin, end), the header between its comment marks; `line` is begin's line.
class Lexer {
  public:
    Lexer(const std::string& text, size_t begin, size_t end, int line, const Where& where)
        : t_(text), pos_(begin), end_(end), line_(line), where_(where) {}
    const Token& peek();
    Token next();

  private:
    void skipBlanks();
    Token lex();
    Token number();
    Token string();
    const std::string& t_;
    size_t pos_, end_;
    int line_;
    const Where& where_;
    Token peeked_;
    bool hasPeeked_ = false;
};

struct Annotation {
    Token key, value;
};

// One `uniform` declaration as written: its known annotations (ReShade's ignored ones dropped).
struct RawParam {
    int line = 0; // of `uniform`
    Token type, name, def;
    std::vector<Annotation> annotations;
};

// Fails unless `name` may be a member of the generated block: [a-z_][a-z0-9_]{0,31}, no gl_ or
// ssao_ prefix, no "__", no GLSL keyword, type or built-in function.
void checkParamName(const Token& name, const Where& where);
// The parameter `raw` declares, every check of user_header.h applied.
UserParam checkParam(const RawParam& raw, const Where& where);

// The #define of an enum item: the parameter's name in capitals (trailing '_' dropped), '_', the
// item's letters and digits in capitals with every other run as one '_' (none at its ends);
// "" when the item holds no letter or digit.
std::string enumDefine(const std::string& param, const std::string& item);

// A number as a message shows it ("0.05", "2e+09", "-inf").
std::string formatNumber(double v);
// User text quoted for a message: at most 40 characters, a NUL shown as \0.
std::string quoted(const std::string& s);

} // namespace ssao::user
