// The checks of one `uniform` declaration of a user technique's header (user_header.h).
#include "techniques/user/user_parse.h"

#include <cctype>
#include <cmath>
#include <set>

namespace ssao::user {

namespace {
// GLSL 4.50's keywords and reserved words, its lower-case type names and built-in functions: a
// member of the block with one of these names would not compile or would hide the function.
const std::set<std::string>& glslWords() {
    static const std::set<std::string> words = {
        // keywords and reserved words
        "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile", "restrict",
        "readonly", "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch",
        "sample", "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else",
        "subroutine", "in", "out", "inout", "true", "false", "invariant", "precise", "discard", "return", "lowp",
        "mediump", "highp", "precision", "struct", "common", "partition", "active", "asm", "class", "union",
        "enum", "typedef", "template", "this", "resource", "goto", "inline", "noinline", "public", "static",
        "extern", "external", "interface", "long", "short", "half", "fixed", "unsigned", "superp", "input",
        "output", "filter", "sizeof", "cast", "namespace", "using", "packed",
        // types
        "void", "bool", "int", "uint", "float", "double", "vec2", "vec3", "vec4", "dvec2", "dvec3", "dvec4",
        "bvec2", "bvec3", "bvec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4", "mat2", "mat3", "mat4",
        "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "dmat2",
        "dmat3", "dmat4", "dmat2x2", "dmat2x3", "dmat2x4", "dmat3x2", "dmat3x3", "dmat3x4", "dmat4x2",
        "dmat4x3", "dmat4x4", "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4",
        // built-in functions
        "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh",
        "acosh", "atanh", "pow", "exp", "log", "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor",
        "trunc", "round", "ceil", "fract", "mod", "modf", "min", "max", "clamp", "mix", "step", "smoothstep",
        "isnan", "isinf", "fma", "frexp", "ldexp", "length", "distance", "dot", "cross", "normalize",
        "faceforward", "reflect", "refract", "transpose", "determinant", "inverse", "equal", "any", "all",
        "not", "texture", "textureProj", "bitfieldExtract", "bitfieldInsert", "bitfieldReverse", "bitCount",
        "findLSB", "findMSB", "uaddCarry", "usubBorrow", "umulExtended", "imulExtended", "barrier", "noise1",
        "noise2", "noise3", "noise4", "main"};
    return words;
}

const char* typeName(UserParam::Type t) {
    switch (t) {
    case UserParam::Type::Float: return "float";
    case UserParam::Type::Int: return "int";
    case UserParam::Type::Bool: return "bool";
    case UserParam::Type::Enum: return "enum";
    }
    return "";
}

// The annotations of one declaration, read with the declaration's own prefix in every message.
struct Reader {
    const RawParam& raw;
    const Where& where;
    UserParam::Type type;

    [[noreturn]] void fail(int line, const std::string& m) const {
        where.fail(line, std::string(typeName(type)) + " parameter '" + raw.name.text + "': " + m);
    }
    const Annotation* find(const char* key) const {
        for (const auto& a : raw.annotations)
            if (a.key.text == key) return &a;
        return nullptr;
    }
    std::string text(const char* key, size_t maxChars, bool mayBeEmpty, bool items = false) const {
        const Annotation* a = find(key);
        if (!a) return "";
        const Token& v = a->value;
        if (v.kind != Token::Kind::String) fail(v.line, std::string(key) + " must be a string");
        if (!v.problem.empty()) fail(v.line, v.problem);
        if (!items && v.text.find('\0') != std::string::npos) fail(v.line, "\\0 is only allowed in ui_items");
        if (v.text.empty() && !mayBeEmpty) fail(v.line, std::string(key) + " is empty");
        if (v.text.size() > maxChars)
            fail(v.line, std::string(key) + " has " + std::to_string(v.text.size()) + " characters; at most " +
                             std::to_string(maxChars));
        return v.text;
    }
    // A number of a float (|v| <= 1e9) or of an int (whole, |v| <= 1e6): an annotation or the default.
    double number(const Token& v, const std::string& what) const {
        const bool isInt = type != UserParam::Type::Float;
        if (v.kind != Token::Kind::Number) fail(v.line, what + " must be a number");
        if (isInt && !v.whole) fail(v.line, what + " must be a whole number (got " + quoted(v.text) + ")");
        if (!std::isfinite(v.number)) fail(v.line, what + " must be finite (got " + quoted(v.text) + ")");
        if (std::fabs(v.number) > (isInt ? 1e6 : 1e9))
            fail(v.line, what + " must be within " + (isInt ? "+-1e6" : "+-1e9") + " (got " + quoted(v.text) + ")");
        return v.number;
    }
    void notFor(const char* key, const char* what) const {
        if (const Annotation* a = find(key)) fail(a->key.line, std::string(key) + " does not apply to " + what);
    }
};

// ui_type's value ("" when absent), which must be one of `allowed` (as the message lists them).
std::string uiType(const Reader& r, const std::set<std::string>& allowed, const std::string& list) {
    const std::string t = r.text("ui_type", 32, false);
    if (!t.empty() && !allowed.count(t)) r.fail(r.find("ui_type")->value.line, "ui_type " + quoted(t) + " is not one of " + list);
    return t;
}

void readRange(const Reader& r, UserParam& p) {
    const Annotation *lo = r.find("ui_min"), *hi = r.find("ui_max"), *step = r.find("ui_step");
    if (!lo || !hi) r.fail(r.raw.line, "needs ui_min and ui_max (the range of its slider, of tuning and of stress runs)");
    p.min = r.number(lo->value, "ui_min");
    p.max = r.number(hi->value, "ui_max");
    if (!(p.min < p.max))
        r.fail(hi->value.line, "ui_min " + formatNumber(p.min) + " must be below ui_max " + formatNumber(p.max));
    if (step) {
        p.step = r.number(step->value, "ui_step");
        if (!(p.step > 0)) r.fail(step->value.line, "ui_step must be above 0 (got " + formatNumber(p.step) + ")");
    }
    p.def = r.number(r.raw.def, "the default");
    if (p.def < p.min || p.def > p.max)
        r.fail(r.raw.def.line, "the default " + formatNumber(p.def) + " is outside [" + formatNumber(p.min) + ", " +
                                   formatNumber(p.max) + "]");
}

void readItems(const Reader& r, UserParam& p) {
    const Annotation* a = r.find("ui_items");
    const int line = a->value.line;
    std::string all = r.text("ui_items", 16 * 34, true, true);
    if (!all.empty() && all.back() == '\0') all.pop_back(); // the trailing \0 is optional
    if (!all.empty())
        for (size_t from = 0;;) {
            const size_t nul = all.find('\0', from);
            p.items.push_back(all.substr(from, nul == std::string::npos ? std::string::npos : nul - from));
            if (nul == std::string::npos) break;
            from = nul + 1;
        }
    if (p.items.empty() || p.items.size() > 16)
        r.fail(line, std::to_string(p.items.size()) + " items; 1 to 16 allowed");
    for (size_t i = 0; i < p.items.size(); ++i) {
        const std::string& it = p.items[i];
        if (it.empty()) r.fail(line, "item " + std::to_string(i + 1) + " is empty");
        if (it.size() > 32)
            r.fail(line, "item " + std::to_string(i + 1) + " has " + std::to_string(it.size()) + " characters; at most 32");
        if (enumDefine(p.name, it).empty()) r.fail(line, "item " + quoted(it) + " has no letter or digit for its #define");
        if (enumDefine(p.name, it).rfind("GL_", 0) == 0)
            r.fail(line, "#define " + enumDefine(p.name, it) + " would begin with GL_ (reserved in GLSL): rename the parameter");
        for (size_t j = 0; j < i; ++j) {
            if (p.items[j] == it) r.fail(line, "item " + quoted(it) + " is listed twice");
            if (enumDefine(p.name, p.items[j]) == enumDefine(p.name, it))
                r.fail(line, "items " + quoted(p.items[j]) + " and " + quoted(it) + " both #define " +
                                 enumDefine(p.name, it) + " (letters and digits are kept, other runs become one _)");
        }
    }
    p.min = 0, p.max = double(p.items.size() - 1);
    const Token& d = r.raw.def;
    if (d.kind != Token::Kind::Number || !d.whole || d.number < 0 || d.number > p.max)
        r.fail(d.line, "the default " + (d.kind == Token::Kind::Number ? formatNumber(d.number) : quoted(d.text)) +
                           " is not an item's index (0 to " + formatNumber(p.max) + ")");
    p.def = d.number + 0.0; // -0 as 0
}
} // namespace

void checkParamName(const Token& name, const Where& where) {
    const std::string& n = name.text;
    bool ok = !n.empty() && n.size() <= 32 && (std::islower(static_cast<unsigned char>(n[0])) || n[0] == '_');
    for (char c : n)
        ok = ok && (std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_');
    const std::string q = "parameter name " + quoted(n);
    if (!ok) where.fail(name.line, q + " must match [a-z_][a-z0-9_]{0,31} (a lower-case GLSL identifier)");
    if (n.rfind("gl_", 0) == 0 || n.rfind("ssao_", 0) == 0)
        where.fail(name.line, q + " may not start with gl_ or ssao_ (reserved for GLSL and for ssaolab's inputs)");
    if (n.find("__") != std::string::npos) where.fail(name.line, q + " may not contain __ (reserved in GLSL)");
    if (glslWords().count(n)) where.fail(name.line, q + " is not allowed: " + quoted(n) + " is a GLSL keyword, type or built-in function");
}

std::string enumDefine(const std::string& param, const std::string& item) {
    std::string word;
    for (char c : item) {
        if (std::isalnum(static_cast<unsigned char>(c))) word += char(std::toupper(static_cast<unsigned char>(c)));
        else if (!word.empty() && word.back() != '_') word += '_';
    }
    while (!word.empty() && word.back() == '_') word.pop_back();
    if (word.empty()) return "";
    std::string head;
    for (char c : param)
        head += char(std::toupper(static_cast<unsigned char>(c)));
    while (!head.empty() && head.back() == '_') head.pop_back();
    return head + "_" + word;
}

UserParam checkParam(const RawParam& raw, const Where& where) {
    UserParam p;
    p.name = raw.name.text;
    p.line = raw.line;
    const std::string& type = raw.type.text;
    p.type = type == "float" ? UserParam::Type::Float : type == "int" ? UserParam::Type::Int : UserParam::Type::Bool;
    Reader r{raw, where, p.type};
    if (p.type == UserParam::Type::Float) {
        uiType(r, {"slider", "drag", "input"}, "slider, drag, input (combo, radio and list are for an int with ui_items)");
        r.notFor("ui_items", "a float");
        readRange(r, p);
    } else if (p.type == UserParam::Type::Int) {
        const std::string t = uiType(r, {"slider", "drag", "input", "combo", "radio", "list"},
                                     "slider, drag, input, combo, radio, list");
        const bool list = t == "combo" || t == "radio" || t == "list";
        if (list && !r.find("ui_items")) r.fail(r.find("ui_type")->value.line, "ui_type " + quoted(t) + " needs ui_items");
        if (!list && r.find("ui_items"))
            r.fail(r.find("ui_items")->key.line, "ui_items needs ui_type combo, radio or list");
        if (list) {
            p.type = r.type = UserParam::Type::Enum;
            for (const char* key : {"ui_min", "ui_max", "ui_step"})
                r.notFor(key, "an enum (its range is its items' indices)");
            readItems(r, p);
        } else {
            readRange(r, p);
        }
    } else {
        uiType(r, {"checkbox"}, "checkbox (or none) for a bool");
        for (const char* key : {"ui_min", "ui_max", "ui_step", "ui_items"})
            r.notFor(key, "a bool");
        p.min = 0, p.max = 1;
        const Token& d = raw.def;
        if (!d.isWord("true") && !d.isWord("false")) r.fail(d.line, "the default must be true or false");
        p.def = d.isWord("true") ? 1 : 0;
    }
    p.label = r.text("ui_label", 48, false);
    if (p.label.empty()) p.label = p.name;
    p.tooltip = r.text("ui_tooltip", 200, true);
    p.unit = r.text("ui_units", 16, true);
    return p;
}

} // namespace ssao::user
