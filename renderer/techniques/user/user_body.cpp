// The body's limits (user_source.h checkUserBody): what a compiler must never be fed from a user's
// file, checked on its tokens with every macro expansion measured - not expanded - under a work
// budget, so a 2 KB #define doubling chain costs a few thousand steps here instead of gigabytes in
// the driver's preprocessor. Each refusal is one "FILE:LINE: message".
#include "techniques/user/user_source.h"

#include "techniques/user/user_parse.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace ssao {

namespace {

struct Tok {
    std::string text;
    int line = 0;
    bool ident = false, number = false;
    size_t col = 0; // where it starts on its line
};

struct Macro {
    bool function = false;
    std::vector<std::string> params;
    std::vector<Tok> body;
};

// What a run of tokens becomes once expanded: its token count and the bracket depth it reaches.
struct Extent {
    double tokens = 0;
    int depth = 0;
};

bool opens(const std::string& t) { return t == "(" || t == "[" || t == "{"; }
bool closes(const std::string& t) { return t == ")" || t == "]" || t == "}"; }

// The tokens of one line of code (comments already blanked), at `line`.
void lexLine(const std::string& s, int line, std::vector<Tok>& out) {
    for (size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (std::isspace(c)) { ++i; continue; }
        size_t j = i + 1;
        const bool ident = std::isalpha(c) || c == '_';
        const bool number = std::isdigit(c) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])));
        if (ident)
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
        else if (number)
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                                    ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E')))) ++j;
        else if (c == '#' && j < s.size() && s[j] == '#')
            ++j; // token pasting, refused by name
        out.push_back({s.substr(i, j - i), line, ident, number, i});
        i = j;
    }
}

class BodyChecker {
  public:
    BodyChecker(const std::string& path) : where_{path} {}
    void run(const std::string& text);

  private:
    void directive(const std::string& line, int no);
    void code(const std::vector<Tok>& toks);
    Extent measure(const std::vector<Tok>& seq, size_t b, size_t e, const Macro* owner, const std::vector<Extent>* args,
                   std::set<std::string>& active, int line);
    size_t callEnd(const std::vector<Tok>& seq, size_t open, size_t e, std::vector<std::pair<size_t, size_t>>& args) const;
    std::optional<double> constant(const std::vector<Tok>& seq, size_t& i, size_t e, int line);
    void arraySize(const std::vector<Tok>& toks, size_t open);
    void step(int line);
    // One more level of the checker's own recursion (measure, constant), given back when the result
    // is destroyed; past kMaxUserNesting x 4 levels the file is refused (its stack stays small).
    struct Level {
        int& n;
        ~Level() { --n; }
    };
    Level deeper(int line, const char* what);

    user::Where where_;
    // Every definition a name was given, each possibly live: #if is not evaluated, so a name defined
    // in two branches is measured as the costlier, and #undef forgets nothing.
    std::map<std::string, std::vector<Macro>> macros_;
    std::map<std::string, double> constInts_;
    double work_ = 0, total_ = 0, statement_ = 0;
    int depth_ = 0;
    int recursion_ = 0; // measure() calls open: macros within macros, calls within arguments
};

BodyChecker::Level BodyChecker::deeper(int line, const char* what) {
    if (++recursion_ > kMaxUserNesting * 4)
        where_.fail(line, std::string(what) + " more than " + std::to_string(kMaxUserNesting * 4) + " levels deep");
    return Level{recursion_};
}

void BodyChecker::step(int line) {
    if (++work_ > kMaxUserExpandedTokens)
        where_.fail(line, "its macros expand past " + std::to_string(kMaxUserExpandedTokens) +
                              " steps (a user technique's text, macros expanded, is bounded)");
}

// The text as the GLSL preprocessor reads it: first every #include line the shader library would
// inline - it matches physical lines whatever a comment says (gl/shader_library.cpp includeTarget) -
// then lines spliced at a backslash-newline, then comments blanked (newlines kept); directives
// handled in order with the code between them. `lines[k]`: the file's line of spliced line k.
void BodyChecker::run(const std::string& text) {
    {
        std::istringstream in(text);
        std::string line;
        for (int no = 1; std::getline(in, line); ++no) {
            size_t i = line.find_first_not_of(" \t");
            if (i == std::string::npos || line[i] != '#') continue;
            i = line.find_first_not_of(" \t", i + 1);
            if (i != std::string::npos && line.compare(i, 7, "include") == 0)
                where_.fail(no, "#include is not available to a user technique (interface 1 offers what it can read)");
        }
    }
    std::string s;
    std::vector<int> lines{1};
    int original = 1;
    for (size_t i = 0; i < text.size(); ++i) {
        const size_t crlf = i + 2 < text.size() && text[i + 1] == '\r' && text[i + 2] == '\n' ? 1 : 0;
        if (text[i] == '\\' && i + 1 + crlf < text.size() && text[i + 1 + crlf] == '\n') { // a splice
            i += 1 + crlf;
            ++original;
            continue;
        }
        s += text[i];
        if (text[i] == '\n') lines.push_back(++original);
    }
    for (size_t i = 0; i + 1 < s.size(); ++i) {
        if (s[i] == '/' && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') s[i++] = ' ';
        } else if (s[i] == '/' && s[i + 1] == '*') {
            const size_t close = s.find("*/", i + 2);
            const size_t end = close == std::string::npos ? s.size() : close + 2;
            for (size_t k = i; k < end; ++k)
                if (s[k] != '\n') s[k] = ' ';
            i = end - 1;
        }
    }
    std::vector<Tok> pending;
    size_t start = 0;
    for (size_t k = 0; start <= s.size(); ++k) {
        size_t end = s.find('\n', start);
        if (end == std::string::npos) end = s.size();
        const std::string line = s.substr(start, end - start);
        const int no = lines[std::min(k, lines.size() - 1)];
        const size_t hash = line.find_first_not_of(" \t\r");
        if (hash != std::string::npos && line[hash] == '#') {
            code(pending);
            pending.clear();
            directive(line.substr(hash + 1), no);
        } else {
            lexLine(line, no, pending);
        }
        start = end + 1;
    }
    code(pending);
}

void BodyChecker::directive(const std::string& rest, int no) {
    std::vector<Tok> toks;
    lexLine(rest, no, toks);
    if (toks.empty()) return;
    const std::string& d = toks[0].text;
    if (d == "line" || d == "version" || d == "extension")
        where_.fail(no, "#" + d + " is not available to a user technique (" +
                            (d == "line" ? std::string("its errors name the file's own lines")
                                         : "ssaolab sets the GLSL version and the extensions the interface needs") + ")");
    for (const Tok& t : toks)
        if (t.text == "##") where_.fail(no, "token pasting (##) is not available to a user technique");
    if ((d == "if" || d == "elif") && toks.size() > 1) {
        std::set<std::string> active;
        measure(toks, 1, toks.size(), nullptr, nullptr, active, no);
    }
    if (d != "define" || toks.size() < 2 || !toks[1].ident) return;
    Macro m;
    size_t i = 2;
    // A function-like macro's '(' follows its name with no blank between.
    if (toks.size() > 2 && toks[2].text == "(" && toks[2].col == toks[1].col + toks[1].text.size()) {
        m.function = true;
        for (i = 3; i < toks.size() && toks[i].text != ")"; ++i)
            if (toks[i].ident) m.params.push_back(toks[i].text);
        ++i;
    }
    int depth = 0;
    for (; i < toks.size(); ++i) {
        depth += opens(toks[i].text) ? 1 : closes(toks[i].text) ? -1 : 0;
        if (depth < 0) break;
        m.body.push_back(toks[i]);
    }
    if (depth != 0) where_.fail(no, "a #define's body must close every bracket it opens, and open every one it closes");
    macros_[toks[1].text].push_back(std::move(m));
}

void BodyChecker::code(const std::vector<Tok>& t) {
    std::set<std::string> active;
    for (size_t i = 0; i < t.size();) {
        const Tok& k = t[i];
        if (k.text == "const" && i + 4 < t.size() && (t[i + 1].text == "int" || t[i + 1].text == "uint") && t[i + 2].ident &&
            t[i + 3].text == "=") { // an array's size may be such a constant
            size_t j = i + 4;
            if (const auto v = constant(t, j, t.size(), t[i].line); v && j < t.size() && t[j].text == ";")
                constInts_[t[i + 2].text] = *v;
        }
        if (k.text == "[") arraySize(t, i);
        size_t next = i + 1;
        Extent x{1, 0};
        const auto m = k.ident ? macros_.find(k.text) : macros_.end();
        if (m != macros_.end()) {
            std::vector<std::pair<size_t, size_t>> spans;
            const bool function = std::any_of(m->second.begin(), m->second.end(), [](const Macro& d) { return d.function; });
            if (function && i + 1 < t.size() && t[i + 1].text == "(") {
                const size_t end = callEnd(t, i + 1, t.size(), spans);
                if (end != std::string::npos) next = end;
            }
            x = measure(t, i, next, nullptr, nullptr, active, k.line);
        } else {
            depth_ = std::max(0, depth_ + (opens(k.text) ? 1 : closes(k.text) ? -1 : 0)); // a stray ')' in #if 0
        }
        if (depth_ + x.depth > kMaxUserNesting)
            where_.fail(k.line, "brackets nest deeper than " + std::to_string(kMaxUserNesting) + " levels");
        total_ += x.tokens, statement_ += x.tokens;
        if (total_ > kMaxUserExpandedTokens)
            where_.fail(k.line, "more than " + std::to_string(kMaxUserExpandedTokens) + " tokens, macros expanded");
        if (statement_ > kMaxUserStatementTokens)
            where_.fail(k.line, "a statement of more than " + std::to_string(kMaxUserStatementTokens) +
                                    " tokens, macros expanded (the compiler's recursion is bounded; split it)");
        if (k.text == ";" || k.text == "{" || k.text == "}") statement_ = 0;
        i = next;
    }
}

Extent BodyChecker::measure(const std::vector<Tok>& seq, size_t b, size_t e, const Macro* owner,
                            const std::vector<Extent>* args, std::set<std::string>& active, int line) {
    // A chain of thousands of #defines, or a call nested in its argument thousands of times.
    const Level level = deeper(line, "macros expand within macros or calls");
    Extent out;
    int cur = 0;
    auto add = [&](const Extent& x) {
        out.tokens += x.tokens;
        out.depth = std::max(out.depth, cur + x.depth);
        if (out.tokens > kMaxUserExpandedTokens)
            where_.fail(line, "its macros expand to more than " + std::to_string(kMaxUserExpandedTokens) + " tokens");
    };
    for (size_t i = b; i < e;) {
        step(line);
        const Tok& k = seq[i];
        cur += opens(k.text) ? 1 : closes(k.text) ? -1 : 0;
        out.depth = std::max(out.depth, cur);
        if (owner && k.ident) {
            const auto p = std::find(owner->params.begin(), owner->params.end(), k.text);
            if (p != owner->params.end() && size_t(p - owner->params.begin()) < args->size()) {
                add((*args)[size_t(p - owner->params.begin())]);
                ++i;
                continue;
            }
        }
        const auto m = k.ident && !active.count(k.text) ? macros_.find(k.text) : macros_.end();
        if (m != macros_.end()) {
            std::vector<std::pair<size_t, size_t>> spans;
            const bool function = std::any_of(m->second.begin(), m->second.end(), [](const Macro& d) { return d.function; });
            const size_t end = function && i + 1 < e && seq[i + 1].text == "(" ? callEnd(seq, i + 1, e, spans) : std::string::npos;
            std::vector<Extent> argx;
            for (const auto& [ab, ae] : spans)
                argx.push_back(measure(seq, ab, ae, owner, args, active, line));
            // Each definition that could apply, the costliest counted; after an object-like one the
            // call's own tokens follow as they are.
            const Extent rest = end == std::string::npos ? Extent{} : measure(seq, i + 1, end, owner, args, active, line);
            Extent worst{-1, 0};
            active.insert(k.text);
            for (const Macro& d : m->second) {
                if (d.function && end == std::string::npos) continue; // a function-like name not called
                Extent x = measure(d.body, 0, d.body.size(), d.function ? &d : nullptr, d.function ? &argx : nullptr, active, line);
                if (!d.function) x.tokens += rest.tokens, x.depth = std::max(x.depth, rest.depth);
                worst.tokens = std::max(worst.tokens, x.tokens), worst.depth = std::max(worst.depth, x.depth);
            }
            active.erase(k.text);
            if (worst.tokens >= 0) {
                add(worst);
                i = end == std::string::npos ? i + 1 : end;
                continue;
            }
        }
        add({1, 0});
        ++i;
    }
    return out;
}

// The index after the ')' closing the call whose '(' is at `open`, the arguments' spans in `args`;
// npos when it does not close before `e`.
size_t BodyChecker::callEnd(const std::vector<Tok>& seq, size_t open, size_t e,
                            std::vector<std::pair<size_t, size_t>>& args) const {
    int depth = 0;
    size_t from = open + 1;
    for (size_t i = open; i < e; ++i) {
        const std::string& t = seq[i].text;
        if (t == "(") ++depth;
        if (t == ")" && --depth == 0) {
            args.emplace_back(from, i);
            return i + 1;
        }
        if (t == "," && depth == 1) args.emplace_back(from, i), from = i + 1;
    }
    args.clear();
    return std::string::npos;
}

// An integer constant expression of literals, #defined and `const int` names, + - * / % and
// brackets; none when it holds anything else (a variable: an index, not a size).
std::optional<double> BodyChecker::constant(const std::vector<Tok>& seq, size_t& i, size_t e, int line) {
    auto primary = [&](auto& self, auto& expr) -> std::optional<double> {
        const Level level = deeper(line, "a constant nests signs, brackets or macros"); // each a level of recursion
        step(line);
        if (i >= e) return std::nullopt;
        const Tok& k = seq[i];
        if (k.text == "-" || k.text == "+") {
            ++i;
            const auto v = self(self, expr);
            return v ? std::optional<double>(k.text == "-" ? -*v : *v) : std::nullopt;
        }
        if (k.text == "(" || ((k.text == "int" || k.text == "uint") && i + 1 < e && seq[i + 1].text == "(")) {
            i += k.text == "(" ? 1 : 2;
            const auto v = expr(expr);
            if (!v || i >= e || seq[i].text != ")") return std::nullopt;
            ++i;
            return std::trunc(*v);
        }
        ++i;
        if (k.number) return std::strtod(k.text.c_str(), nullptr);
        if (const auto c = constInts_.find(k.text); c != constInts_.end()) return c->second;
        const auto m = macros_.find(k.text);
        if (m == macros_.end()) return std::nullopt;
        std::optional<double> largest; // of every definition that could apply
        for (const Macro& d : m->second) {
            size_t j = 0;
            const auto v = d.function ? std::nullopt : constant(d.body, j, d.body.size(), line);
            if (!v || j != d.body.size()) return std::nullopt;
            if (!largest || std::fabs(*v) > std::fabs(*largest)) largest = v;
        }
        return largest;
    };
    auto term = [&](auto& expr) -> std::optional<double> {
        auto v = primary(primary, expr);
        while (v && i < e && (seq[i].text == "*" || seq[i].text == "/" || seq[i].text == "%")) {
            const std::string op = seq[i++].text;
            const auto r = primary(primary, expr);
            if (!r || (op != "*" && *r == 0)) return std::nullopt;
            v = op == "*" ? *v * *r : op == "/" ? std::trunc(*v / *r) : std::fmod(*v, *r);
        }
        return v;
    };
    auto expr = [&](auto& self) -> std::optional<double> {
        auto v = term(self);
        while (v && i < e && (seq[i].text == "+" || seq[i].text == "-")) {
            const std::string op = seq[i++].text;
            const auto r = term(self);
            if (!r) return std::nullopt;
            v = op == "+" ? *v + *r : *v - *r;
        }
        return v;
    };
    return expr(expr);
}

// `[N]` (and `[N][M]...` after it) of a constant N: the elements an array of it holds.
void BodyChecker::arraySize(const std::vector<Tok>& toks, size_t open) {
    double elements = 1;
    for (size_t at = open; at < toks.size() && toks[at].text == "[";) {
        size_t j = at + 1;
        auto v = constant(toks, j, toks.size(), toks[open].line);
        if (!v || j >= toks.size() || toks[j].text != "]") return;
        // An unsigned literal makes the size unsigned: -1u is 4294967295.
        const bool unsignedSize = std::any_of(toks.begin() + long(at) + 1, toks.begin() + long(j), [](const Tok& t) {
            return t.number && (t.text.back() == 'u' || t.text.back() == 'U');
        });
        if (unsignedSize) v = std::fmod(std::fmod(*v, 4294967296.0) + 4294967296.0, 4294967296.0);
        elements *= std::max(1.0, std::fabs(*v));
        if (elements > kMaxUserArrayElements)
            where_.fail(toks[open].line, "an array of " + user::formatNumber(elements) + " elements; a user technique's arrays hold at most " +
                                             std::to_string(kMaxUserArrayElements));
        at = j + 1;
    }
}

} // namespace

void checkUserBody(const std::string& text, const std::string& path) {
    BodyChecker(path).run(text);
}

} // namespace ssao
