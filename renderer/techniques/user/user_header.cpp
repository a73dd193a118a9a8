#include "techniques/user/user_header.h"

#include "techniques/user/user_parse.h"
#include "util/closest_name.h"
#include "util/error.h"

#include <algorithm>
#include <map>

namespace ssao {

using user::Token;

namespace {
const char* const kStatements = "a header holds interface, label, summary and uniform declarations";
const std::vector<std::string> kKnown = {"ui_type", "ui_min",   "ui_max",     "ui_step",
                                         "ui_label", "ui_tooltip", "ui_units", "ui_items"};
// ReShade annotations that mean nothing here: accepted so ReShade headers carry over, then dropped.
const std::vector<std::string> kIgnored = {"ui_category", "ui_category_closed", "ui_spacing",
                                           "ui_text",     "hidden",             "source"};

struct HeaderSpan {
    size_t open = 0, close = 0; // of its "/*" and its "*/"
    int line = 0;               // of its "/*"
};

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// The first block comment opening with "ssaolab", comments read as GLSL reads them; a second
// one, an unterminated one or none is an error.
HeaderSpan findHeader(const std::string& t, const user::Where& where) {
    HeaderSpan found;
    int line = 1;
    for (size_t i = 0, n = t.size(); i < n;) {
        if (t[i] == '\n') {
            ++line, ++i;
        } else if (t.compare(i, 2, "//") == 0) {
            i = std::min(t.find('\n', i), n);
        } else if (t.compare(i, 2, "/*") == 0) {
            const size_t end = t.find("*/", i + 2);
            const bool header = t.compare(i + 2, 7, "ssaolab") == 0 &&
                                (i + 9 == n || blank(t[i + 9]) || t.compare(i + 9, 2, "*/") == 0);
            if (header && found.line)
                where.fail(line, "a second ssaolab header (the first is at line " + std::to_string(found.line) +
                                     "): a file has one");
            if (header && end == std::string::npos) where.fail(line, "the ssaolab header opened here has no closing */");
            if (header) found = {i, end, line};
            if (end == std::string::npos) break; // an unterminated comment in the body: the compiler's to report
            line += int(std::count(t.begin() + long(i), t.begin() + long(end), '\n'));
            i = end + 2;
        } else {
            ++i;
        }
    }
    if (!found.line)
        where.fail(1, "no ssaolab header: a user technique declares its parameters in /*ssaolab interface = 1; ... */");
    return found;
}

class HeaderParser {
  public:
    HeaderParser(user::Lexer& lx, const user::Where& where) : lx_(lx), where_(where) {}
    UserHeader run(int headerLine);

  private:
    void expect(char punct, const Token& after, const std::string& what) {
        if (!lx_.next().is(punct)) where_.fail(after.line, std::string("expected '") + punct + "' after " + what);
    }
    std::string stringStatement(const Token& key, size_t maxChars, bool mayBeEmpty);
    void interfaceStatement(const Token& key);
    void uniform(const Token& kw);
    Token annotations(user::RawParam& raw);
    void addParam(const UserParam& p, const Token& name);

    user::Lexer& lx_;
    const user::Where& where_;
    UserHeader h_;
    bool interface_ = false, label_ = false, summary_ = false;
    std::map<std::string, int> names_;            // parameter -> its line
    std::map<std::string, std::string> defines_; // enum #define -> whose item
};

UserHeader HeaderParser::run(int headerLine) {
    while (lx_.peek().kind != Token::Kind::End) {
        const Token t = lx_.next();
        if (t.isWord("interface")) {
            interfaceStatement(t);
        } else if (t.isWord("label")) {
            if (label_) where_.fail(t.line, "label is given twice");
            label_ = true, h_.label = stringStatement(t, 48, false);
        } else if (t.isWord("summary")) {
            if (summary_) where_.fail(t.line, "summary is given twice");
            summary_ = true, h_.summary = stringStatement(t, 160, true);
        } else if (t.isWord("uniform")) {
            uniform(t);
        } else if (t.kind == Token::Kind::Ident) {
            where_.fail(t.line, "unknown statement " + user::quoted(t.text) +
                                    didYouMean(t.text, {"interface", "label", "summary", "uniform"}) + "; " + kStatements);
        } else {
            where_.fail(t.line, "unexpected " + (t.kind == Token::Kind::Punct ? user::quoted(t.text)
                                                 : t.kind == Token::Kind::Number ? "number " + user::quoted(t.text)
                                                                                   : std::string("string")) +
                                    "; " + kStatements);
        }
    }
    if (!interface_)
        where_.fail(headerLine, "the header has no 'interface = 1;' (the input interface the body is written against)");
    return h_;
}

void HeaderParser::interfaceStatement(const Token& key) {
    if (interface_) where_.fail(key.line, "interface is given twice");
    interface_ = true;
    expect('=', key, "interface");
    const Token v = lx_.next();
    if (v.kind != Token::Kind::Number || !v.whole || v.number != kUserInterfaceVersion)
        where_.fail(v.line, "interface " + (v.kind == Token::Kind::Number ? v.text.substr(0, 24) : user::quoted(v.text)) +
                                " is not supported; this ssaolab supports interface " + std::to_string(kUserInterfaceVersion));
    expect(';', v, "interface = " + v.text);
    h_.interface = kUserInterfaceVersion;
}

std::string HeaderParser::stringStatement(const Token& key, size_t maxChars, bool mayBeEmpty) {
    expect('=', key, key.text);
    const Token v = lx_.next();
    const std::string& k = key.text;
    if (v.kind != Token::Kind::String) where_.fail(v.kind == Token::Kind::End ? key.line : v.line, k + " must be a string");
    if (!v.problem.empty()) where_.fail(v.line, v.problem);
    if (v.text.find('\0') != std::string::npos) where_.fail(v.line, "\\0 is only allowed in ui_items");
    if (v.text.empty() && !mayBeEmpty) where_.fail(v.line, k + " is empty");
    if (v.text.size() > maxChars)
        where_.fail(v.line, k + " has " + std::to_string(v.text.size()) + " characters; at most " + std::to_string(maxChars));
    expect(';', v, "the value of " + k);
    return v.text;
}

void HeaderParser::uniform(const Token& kw) {
    if (int(h_.params.size()) == kMaxUserParams)
        where_.fail(kw.line, "more than " + std::to_string(kMaxUserParams) + " parameters: a user technique has at most " +
                                 std::to_string(kMaxUserParams));
    user::RawParam raw;
    raw.line = kw.line;
    raw.type = lx_.next();
    if (raw.type.kind != Token::Kind::Ident) where_.fail(kw.line, "expected a type (float, int or bool) after uniform");
    if (!raw.type.isWord("float") && !raw.type.isWord("int") && !raw.type.isWord("bool"))
        where_.fail(raw.type.line, "type " + user::quoted(raw.type.text) + " is not supported; a parameter is float, int or bool");
    const char* const noArrays = "arrays are not supported: a parameter is one float, int or bool";
    if (lx_.peek().is('[')) where_.fail(lx_.peek().line, noArrays);
    raw.name = lx_.next();
    if (raw.name.kind != Token::Kind::Ident)
        where_.fail(raw.type.line, "expected the parameter's name after " + user::quoted(raw.type.text));
    if (lx_.peek().is('[')) where_.fail(lx_.peek().line, "parameter " + user::quoted(raw.name.text) + ": " + noArrays);
    user::checkParamName(raw.name, where_);
    const std::string q = "parameter " + user::quoted(raw.name.text);
    const auto seen = names_.find(raw.name.text);
    if (seen != names_.end())
        where_.fail(raw.name.line, q + " is declared twice (first at line " + std::to_string(seen->second) + ")");
    Token last = raw.name;
    if (lx_.peek().is('<')) {
        lx_.next();
        last = annotations(raw);
    }
    const Token& eq = lx_.peek();
    if (!eq.is('=')) {
        if (last.is('>') || eq.is(';') || eq.kind == Token::Kind::End || eq.isWord("uniform"))
            where_.fail(last.line, q + " has no default: end the declaration with '= VALUE;'");
        where_.fail(last.line, "expected '<' or '=' after " + q);
    }
    const Token equals = lx_.next();
    raw.def = lx_.next();
    if (raw.def.kind == Token::Kind::End || raw.def.kind == Token::Kind::Punct)
        where_.fail(equals.line, q + " has no default: end the declaration with '= VALUE;'");
    expect(';', raw.def, "the default of " + user::quoted(raw.name.text));
    addParam(user::checkParam(raw, where_), raw.name);
}

// `< key = value; ... >` after `<`: keeps the known annotations, drops ReShade's ignored ones.
Token HeaderParser::annotations(user::RawParam& raw) {
    std::vector<std::string> all = kKnown;
    all.insert(all.end(), kIgnored.begin(), kIgnored.end());
    const std::string q = "parameter " + user::quoted(raw.name.text);
    for (;;) {
        const Token k = lx_.next();
        if (k.is('>')) return k;
        if (k.kind == Token::Kind::End) where_.fail(k.line, "the annotations of " + q + " have no closing '>'");
        if (k.kind != Token::Kind::Ident) where_.fail(k.line, "expected an annotation or '>' in " + q);
        const bool known = std::count(kKnown.begin(), kKnown.end(), k.text) > 0;
        if (!known && !std::count(kIgnored.begin(), kIgnored.end(), k.text))
            where_.fail(k.line, "unknown annotation " + user::quoted(k.text) + didYouMean(k.text, all) +
                                    "; allowed: ui_type, ui_min, ui_max, ui_step, ui_label, ui_tooltip, ui_units, "
                                    "ui_items (and ReShade's ui_category, ui_category_closed, ui_spacing, ui_text, "
                                    "hidden and source, ignored)");
        for (const auto& a : raw.annotations)
            if (a.key.text == k.text) where_.fail(k.line, k.text + " is given twice in " + q);
        expect('=', k, k.text);
        const Token v = lx_.next();
        const bool value = v.kind == Token::Kind::String || v.kind == Token::Kind::Number || v.isWord("true") ||
                           v.isWord("false");
        if (!value) where_.fail(v.kind == Token::Kind::End ? k.line : v.line, "expected a value after " + k.text + " =");
        expect(';', v, "the value of " + k.text);
        if (known) raw.annotations.push_back({k, v});
    }
}

// Records the parameter, its name and its enum #defines, each unique among all of them.
void HeaderParser::addParam(const UserParam& p, const Token& name) {
    auto clash = [&](const std::string& id) {
        const auto d = defines_.find(id);
        return d == defines_.end() ? std::string() : d->second;
    };
    if (!clash(p.name).empty())
        where_.fail(name.line, "parameter name " + user::quoted(p.name) + " is already the #define of " + clash(p.name));
    names_[p.name] = p.line;
    for (const auto& item : p.items) {
        const std::string d = user::enumDefine(p.name, item);
        if (!clash(d).empty() || names_.count(d))
            where_.fail(p.line, "enum parameter " + user::quoted(p.name) + ": #define " + d + " is already " +
                                    (names_.count(d) ? "a parameter's name" : "made by " + clash(d)));
        defines_[d] = "parameter " + user::quoted(p.name) + " item " + user::quoted(item);
    }
    h_.params.push_back(p);
}
} // namespace

std::string userTechniqueName(const std::string& path, const std::vector<std::string>& builtinIds) {
    auto fail = [&](const std::string& m) -> void { throw Error(oneLine(path + ": " + m)); };
    const std::string suffix = ".ao.glsl";
    const size_t slash = path.find_last_of('/');
    const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
    if (file.size() < suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
        fail("a user technique's file is named NAME.ao.glsl");
    const std::string name = file.substr(0, file.size() - suffix.size());
    bool ok = !name.empty() && name.size() <= 24 && name[0] >= 'a' && name[0] <= 'z';
    for (char c : name)
        ok = ok && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_');
    if (!ok) fail("the technique's name " + user::quoted(name) + " must match [a-z][a-z0-9_]{0,23}");
    if (std::count(builtinIds.begin(), builtinIds.end(), name))
        fail("'" + name + "' is a built-in technique: name the file otherwise");
    return name;
}

UserHeader parseUserHeader(const std::string& text, const std::string& file, const std::vector<std::string>& builtinIds) {
    const std::string name = userTechniqueName(file, builtinIds);
    const user::Where where{file};
    if (text.size() > kMaxUserFileBytes)
        where.fail(1, "the file is " + std::to_string(text.size()) + " bytes; a user technique is at most " +
                          std::to_string(kMaxUserFileBytes) + " bytes (256 KiB)");
    const HeaderSpan span = findHeader(text, where);
    if (span.close + 2 - span.open > kMaxUserHeaderBytes)
        where.fail(span.line, "the header is " + std::to_string(span.close + 2 - span.open) + " bytes; at most " +
                                  std::to_string(kMaxUserHeaderBytes) + " bytes (16 KiB)");
    user::Lexer lexer(text, span.open + 9, span.close, span.line, where);
    UserHeader h = HeaderParser(lexer, where).run(span.line);
    if (h.label.empty()) h.label = name;
    return h;
}

} // namespace ssao
