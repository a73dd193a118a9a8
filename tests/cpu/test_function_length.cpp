// The house rule, checked on the source tree: no function of the program (renderer/, app/) has a
// body over 80 lines, data tables aside. A function body is what lies between the brace that opens
// a definition (after its parameter list) at namespace or class scope and the brace that closes it.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
constexpr int kMaxBodyLines = 80;

// Functions whose body is one table (an initializer list, a row per entry): long by content, not
// by steps. Keyed by file name and function.
const std::map<std::string, std::string> kTables = {
    // The parameter table's core rows: one braced list, a row per shared setting.
    {"core_rows.cpp", "coreRows"},
};

bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The text with comments, string and character literals blanked (newlines kept, so lines count).
std::string codeOnly(const std::string& t) {
    std::string out;
    out.reserve(t.size());
    const size_t n = t.size();
    auto keepNewlines = [&](size_t from, size_t to) {
        for (size_t k = from; k < to && k < n; ++k)
            if (t[k] == '\n') out += '\n';
    };
    for (size_t i = 0; i < n;) {
        if (t.compare(i, 2, "//") == 0) {
            i = std::min(t.find('\n', i), n);
        } else if (t.compare(i, 2, "/*") == 0) {
            const size_t end = std::min(t.find("*/", i + 2), n - 2) + 2;
            keepNewlines(i, end), i = end;
        } else if (t[i] == 'R' && i + 1 < n && t[i + 1] == '"' && (i == 0 || !identChar(t[i - 1]) || t[i - 1] == '8' ||
                                                                   t[i - 1] == 'L' || t[i - 1] == 'u' || t[i - 1] == 'U')) {
            const size_t open = t.find('(', i);
            const std::string close = ")" + t.substr(i + 2, open - i - 2) + "\"";
            const size_t end = std::min(t.find(close, open), n) + close.size();
            out += "\"\"", keepNewlines(i, end), i = end;
        } else if (t[i] == '"' || (t[i] == '\'' && !(i > 0 && identChar(t[i - 1]) && i + 1 < n &&
                                                     std::isxdigit(static_cast<unsigned char>(t[i + 1]))))) {
            const char q = t[i];
            size_t j = i + 1;
            while (j < n && t[j] != q && t[j] != '\n') j += t[j] == '\\' ? 2 : 1;
            out += q, out += q, i = j + 1;
        } else {
            out += t[i++];
        }
    }
    return out;
}

// The name of the function whose body opens at `brace`, or "" when the brace opens something
// else (a namespace, class, initializer, or a control statement's block).
std::string definitionAt(const std::string& code, size_t brace) {
    size_t e = brace;
    auto skipSpace = [&] {
        while (e > 0 && std::isspace(static_cast<unsigned char>(code[e - 1]))) --e;
    };
    skipSpace();
    for (bool trimmed = true; trimmed;) { // trailing qualifiers and a trailing return type
        trimmed = false;
        for (const char* q : {"const", "noexcept", "override", "final", "mutable"}) {
            const size_t len = std::string(q).size();
            if (e >= len && code.compare(e - len, len, q) == 0 && (e == len || !identChar(code[e - len - 1]))) {
                e -= len, skipSpace(), trimmed = true;
            }
        }
        const size_t arrow = code.rfind("->", e);
        if (arrow != std::string::npos && e - arrow < 80 && code.find_first_of("(){};", arrow) >= e) {
            e = arrow, skipSpace(), trimmed = true;
        }
    }
    if (e == 0 || code[e - 1] != ')') return "";
    int depth = 0;
    size_t open = e - 1;
    for (;; --open) {
        depth += code[open] == ')' ? 1 : code[open] == '(' ? -1 : 0;
        if (depth == 0 || open == 0) break;
    }
    size_t end = open;
    while (end > 0 && std::isspace(static_cast<unsigned char>(code[end - 1]))) --end;
    if (end > 0 && code[end - 1] == ']') return "(lambda)";
    const size_t op = code.rfind("operator", end);
    if (op != std::string::npos && end - op <= 11 && code.find_first_of("{};", op) >= end) return "operator";
    size_t begin = end;
    while (begin > 0 && (identChar(code[begin - 1]) || code[begin - 1] == ':' || code[begin - 1] == '~')) --begin;
    const std::string name = code.substr(begin, end - begin);
    for (const char* keyword : {"if", "for", "while", "switch", "catch", ""})
        if (name == keyword) return "";
    return name;
}

struct LongFunction {
    std::string file, name;
    int line = 0, body = 0;
};

std::vector<LongFunction> longFunctions(const fs::path& root, const std::string& rel) {
    std::ifstream in(root / rel);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string code = codeOnly(ss.str());
    struct Open {
        std::string function; // "" when the brace opens no function
        int line;
    };
    std::vector<Open> open;
    std::vector<LongFunction> out;
    int line = 1, inFunction = 0;
    for (size_t i = 0; i < code.size(); ++i) {
        if (code[i] == '\n') {
            ++line;
        } else if (code[i] == '{') {
            const std::string name = inFunction ? std::string() : definitionAt(code, i);
            inFunction += !name.empty();
            open.push_back({name, line});
        } else if (code[i] == '}' && !open.empty()) {
            const Open o = open.back();
            open.pop_back();
            if (o.function.empty()) continue;
            --inFunction;
            const int body = line - o.line - 1;
            if (body > kMaxBodyLines) out.push_back({rel, o.function, o.line, body});
        }
    }
    return out;
}
} // namespace

TEST(FunctionLength, NoFunctionOfTheProgramIsOver80LinesOutsideTheTables) {
    const fs::path root(SSAOLAB_SOURCE_DIR);
    int files = 0;
    std::vector<LongFunction> found;
    for (const char* top : {"renderer", "app"})
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
            ++files;
            for (auto& f : longFunctions(root, fs::relative(e.path(), root).generic_string())) found.push_back(f);
        }
    EXPECT_GT(files, 100);
    int tables = 0;
    for (const auto& f : found) {
        const std::string file = fs::path(f.file).filename().string();
        const auto t = kTables.find(file);
        const bool table = t != kTables.end() && t->second == f.name;
        std::printf("%s:%d %s: %d lines%s\n", f.file.c_str(), f.line, f.name.c_str(), f.body, table ? " (table)" : "");
        tables += table;
        EXPECT_TRUE(table) << f.file << ":" << f.line << " " << f.name << " has a body of " << f.body
                           << " lines (at most " << kMaxBodyLines << "): split it by its steps";
    }
    EXPECT_EQ(tables, int(kTables.size())) << "a table in kTables is gone or short now: drop it from the list";
}

TEST(FunctionLength, TheScannerFindsBodiesAndSkipsBlocksAndLiterals) {
    // Measured on a written file: a function, a member with qualifiers, a control block, braces in
    // strings and comments, and a lambda inside a function (part of its body).
    const fs::path dir = fs::path(SSAOLAB_TEST_TMP) / "function_length";
    fs::create_directories(dir);
    std::string body;
    for (int i = 0; i < 81; ++i)
        body += "    x += " + std::to_string(i) + "; // {\n";
    std::ofstream(dir / "a.cpp") << "namespace n {\nstruct S {\n    int f(int x) const noexcept {\n" << body
                                 << "        return x;\n    }\n};\n"
                                 << "int g(int x) {\n    if (x) {\n" << body << "    }\n    auto l = [](int y) {\n"
                                 << body << "    };\n    const char* s = \"}\";\n    return x;\n}\n"
                                 << "int h() {\n    return 1;\n}\n}\n";
    const auto found = longFunctions(dir, "a.cpp");
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].name, "f");
    EXPECT_EQ(found[0].body, 82);
    EXPECT_EQ(found[1].name, "g");
    EXPECT_EQ(found[1].line, 88);
    EXPECT_EQ(found[1].body, 168);
}
