// A user technique's parameter header (NAME.ao.glsl, techniques/user/user_header.h): what it
// parses to, every check with its exact line, the GLSL generated from it (compiled by Khronos'
// glslangValidator, started through util/process.h), the std140 bytes and the file's hash.
#include "techniques/technique.h"
#include "techniques/user/user_header.h"
#include "util/process.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

using namespace ssao;
using ssaotest::errorOf;

namespace {
std::vector<std::string> builtinIds() {
    std::vector<std::string> ids;
    for (const auto& t : techniques())
        ids.push_back(t.id);
    return ids;
}

const std::string kFile = "dir/crytek.ao.glsl";

UserHeader parse(const std::string& text) {
    return parseUserHeader(text, kFile, builtinIds());
}

// Every type, annotations across lines, escapes, an 'f' suffix, exponents, a comment before the header.
const std::string kValid = "// A user technique for the tests.\n"                                     // 1
                           "/*ssaolab\n"                                                             // 2
                           "interface = 1;                 // the input interface\n"                 // 3
                           "label = \"Crytek-style kernel\";\n"                                      // 4
                           "summary = \"one line\";\n"                                               // 5
                           "uniform float radius_scale < ui_type = \"slider\"; ui_min = 0.25; ui_max = 4.0; ui_step = 0.05;\n" // 6
                           "    ui_label = \"Radius scale\"; ui_units = \" x R\"; ui_tooltip = \"Scales the world radius R.\"; > = 1.0;\n" // 7
                           "uniform int samples < ui_type = \"slider\"; ui_min = 1; ui_max = 64; > = 16;\n" // 8
                           "uniform bool use_normals < ui_label = \"Use normals\"; > = true;\n"      // 9
                           "uniform int falloff < ui_type = \"combo\"; ui_items = \"none\\0linear\\0smooth\\0\"; > = 1;\n" // 10
                           "uniform float bias\n"                                                    // 11
                           "   < ui_min = -1e-2; ui_max = 2.5e1f; ui_tooltip = \"Say \\\"hi\\\" \\\\ there\"; >\n" // 12
                           "   = -0.5e-2;\n"                                                         // 13
                           "uniform int shape < ui_type = \"radio\"; ui_items = \"no falloff\\0 1/r^2 \\0Linear\"; > = 2;\n" // 14
                           "*/\n"                                                                    // 15
                           "out vec4 c;\n"                                                           // 16
                           "void main() { c = vec4(radius_scale, float(samples), float(use_normals), bias)\n" // 17
                           "    + float(FALLOFF_SMOOTH + falloff + SHAPE_1_R_2 + SHAPE_NO_FALLOFF + SHAPE_LINEAR); }\n"; // 18

void expectParam(const UserParam& p, const std::string& name, UserParam::Type type, double min, double max,
                 double step, double def, int line) {
    SCOPED_TRACE(name);
    EXPECT_EQ(p.name, name);
    EXPECT_EQ(p.type, type);
    EXPECT_DOUBLE_EQ(p.min, min);
    EXPECT_DOUBLE_EQ(p.max, max);
    EXPECT_DOUBLE_EQ(p.step, step);
    EXPECT_DOUBLE_EQ(p.def, def);
    EXPECT_EQ(p.line, line);
}
} // namespace

TEST(UserHeader, AValidHeaderWithEveryTypeParsesToItsRows) {
    const UserHeader h = parse(kValid);
    EXPECT_EQ(h.interface, 1);
    EXPECT_EQ(h.label, "Crytek-style kernel");
    EXPECT_EQ(h.summary, "one line");
    ASSERT_EQ(h.params.size(), 6u);
    using T = UserParam::Type;
    expectParam(h.params[0], "radius_scale", T::Float, 0.25, 4.0, 0.05, 1.0, 6);
    EXPECT_EQ(h.params[0].label, "Radius scale");
    EXPECT_EQ(h.params[0].unit, " x R");
    EXPECT_EQ(h.params[0].tooltip, "Scales the world radius R.");
    expectParam(h.params[1], "samples", T::Int, 1, 64, 0, 16, 8);
    EXPECT_EQ(h.params[1].label, "samples");
    EXPECT_EQ(h.params[1].tooltip, "");
    EXPECT_EQ(h.params[1].unit, "");
    expectParam(h.params[2], "use_normals", T::Bool, 0, 1, 0, 1, 9);
    EXPECT_EQ(h.params[2].label, "Use normals");
    expectParam(h.params[3], "falloff", T::Enum, 0, 2, 0, 1, 10);
    EXPECT_EQ(h.params[3].items, (std::vector<std::string>{"none", "linear", "smooth"}));
    expectParam(h.params[4], "bias", T::Float, -0.01, 25, 0, -0.005, 11);
    EXPECT_EQ(h.params[4].tooltip, "Say \"hi\" \\ there");
    expectParam(h.params[5], "shape", T::Enum, 0, 2, 0, 2, 14);
    EXPECT_EQ(h.params[5].items, (std::vector<std::string>{"no falloff", " 1/r^2 ", "Linear"}));
}

TEST(UserHeader, TheLabelDefaultsToTheFileNameAndTheRestIsOptional) {
    const UserHeader h = parseUserHeader("/*ssaolab interface = 1; */ void main() {}", "a/b/my_ao.ao.glsl", builtinIds());
    EXPECT_EQ(h.label, "my_ao");
    EXPECT_EQ(h.summary, "");
    EXPECT_TRUE(h.params.empty());
    // Windows line ends and a licence comment ahead of the header.
    const UserHeader crlf = parse("/* licence */\r\n/*ssaolab\r\ninterface = 1;\r\n\r\nuniform bool b = false;\r\n*/\r\n");
    ASSERT_EQ(crlf.params.size(), 1u);
    EXPECT_EQ(crlf.params[0].line, 5);
    EXPECT_EQ(crlf.params[0].def, 0);
}

TEST(UserHeader, ReShadeAnnotationsWithNoMeaningHereAreAcceptedAndIgnored) {
    const UserHeader h = parse("/*ssaolab\ninterface = 1;\n"
                               "uniform float strength < ui_category = \"Main\"; ui_category_closed = true; ui_spacing = 2;\n"
                               "  ui_text = \"Some words\\nmore \\t\xc2\xb0\"; hidden = false; source = \"x\"; ui_min = 0; ui_max = 1;\n"
                               "  ui_type = \"drag\"; > = 0.5;\n"
                               "uniform int n < ui_type = \"input\"; ui_min = -3; ui_max = 3; ui_step = 2; ui_category = \"Main\"; > = -1;\n"
                               "uniform bool on < ui_type = \"checkbox\"; hidden = true; > = true;\n*/\n");
    ASSERT_EQ(h.params.size(), 3u);
    EXPECT_EQ(h.params[0].label, "strength");
    EXPECT_EQ(h.params[0].tooltip, "");
    EXPECT_DOUBLE_EQ(h.params[0].def, 0.5);
    EXPECT_DOUBLE_EQ(h.params[1].step, 2);
    EXPECT_DOUBLE_EQ(h.params[1].def, -1);
    EXPECT_DOUBLE_EQ(h.params[2].def, 1);
}

TEST(UserHeader, CommentsInsideTheHeaderAreIgnoredButNotInsideStrings) {
    const UserHeader h = parse("/*ssaolab\n"
                               "// a whole-line comment; uniform int x < ui_min = 0; ui_max = 1; > = 0;\n"
                               "interface = 1; // trailing\n"
                               "uniform int n < ui_min = 1; // between annotations\n"
                               "  ui_max = 8; > = 2; // after\n"
                               "uniform bool b < ui_label = \"a // not a comment\"; > = false;\n"
                               "*/\n"
                               "// /*ssaolab in a line comment is no header */\n"
                               "/* ssaolab after a blank is no header */ /*ssaolabs neither */\n"
                               "void main() {}\n");
    ASSERT_EQ(h.params.size(), 2u);
    EXPECT_EQ(h.params[0].name, "n");
    EXPECT_EQ(h.params[0].line, 4);
    EXPECT_EQ(h.params[1].label, "a // not a comment");
}

namespace {
struct Bad {
    std::string text;
    int line;
    std::string message;
};

// A file whose header's first statement is interface = 1 (line 2): `body` starts on line 3.
std::string header(const std::string& body) {
    return "/*ssaolab\ninterface = 1;\n" + body + "*/\nvoid main() {}\n";
}

std::string params(int n) {
    std::string s;
    for (int i = 0; i < n; ++i)
        s += "uniform bool p" + std::to_string(i) + " = true;\n";
    return s;
}

std::string items(int n) {
    std::string s;
    for (int i = 0; i < n; ++i)
        s += "i" + std::to_string(i) + "\\0";
    return s;
}

const std::string kRange = "ui_min = 0; ui_max = 1;";

std::vector<Bad> badHeaders() {
    return {
        {"void main() {}\n", 1, "no ssaolab header"},
        {header("") + "/* fine */\n/*ssaolab\ninterface = 1; */\n", 6, "a second ssaolab header (the first is at line 1)"},
        {"\n/*ssaolab\ninterface = 1;\n", 2, "no closing */"},
        {"/*ssaolab\nlabel = \"x\";\n*/\n", 1, "interface = 1;"},
        {"/*ssaolab\n\ninterface = 2;\n*/\n", 3, "interface 2 is not supported; this ssaolab supports interface 1"},
        {"/*ssaolab\ninterface = 1;\ninterface = 1;\n*/\n", 3, "interface is given twice"},
        {header("") + std::string(kMaxUserFileBytes, ' '), 1, "at most 262144 bytes (256 KiB)"},
        {header("// " + std::string(kMaxUserHeaderBytes, 'x') + "\n"), 1, "at most 16384 bytes (16 KiB)"},
        {header("version = 1;\n"), 3, "unknown statement 'version'"},
        {header("uniform int n < " + kRange + " >;\n"), 3, "parameter 'n' has no default"},
        {header("uniform int n < " + kRange + " > = 1\nuniform bool b = true;\n"), 3, "expected ';' after the default of 'n'"},
        {header("uniform int n < ui_min = 0\n  ui_max = 1; > = 1;\n"), 3, "expected ';' after the value of ui_min"},
        {header("uniform int n < ui_min 0; ui_max = 1; > = 1;\n"), 3, "expected '=' after ui_min"},
        {header("\nlabel = \"abc;\n"), 4, "unterminated string"},
        {header("uniform float w[4] < " + kRange + " > = 0;\n"), 3, "arrays are not supported"},
        {header("uniform float[4] w < " + kRange + " > = 0;\n"), 3, "arrays are not supported"},
        {header("\nuniform vec3 c = 1;\n"), 4, "type 'vec3' is not supported; a parameter is float, int or bool"},
        {header("uniform float x < ui_min = 0;\n ui_lable = \"X\"; ui_max = 1; > = 0;\n"), 4,
         "unknown annotation 'ui_lable' (did you mean ui_label?)"},
        {header("uniform float x < " + kRange + " ui_min = 0; > = 0;\n"), 3, "ui_min is given twice"},
        {header(params(24) + "uniform bool extra = true;\n"), 27, "more than 24 parameters"},
        {header("uniform float Radius < " + kRange + " > = 0;\n"), 3, "parameter name 'Radius'"},
        {header("uniform float gl_x < " + kRange + " > = 0;\n"), 3, "may not start with gl_ or ssao_"},
        {header("uniform float ssao_x < " + kRange + " > = 0;\n"), 3, "may not start with gl_ or ssao_"},
        {header("uniform float a__b < " + kRange + " > = 0;\n"), 3, "may not contain __"},
        {header("uniform float out < " + kRange + " > = 0;\n"), 3, "'out' is a GLSL keyword"},
        {header("uniform float max < " + kRange + " > = 0;\n"), 3, "'max' is a GLSL keyword"},
        {header("uniform float " + std::string(33, 'a') + " < " + kRange + " > = 0;\n"), 3, "[a-z_][a-z0-9_]{0,31}"},
        {header("uniform bool b = true;\nuniform bool b = false;\n"), 4, "parameter 'b' is declared twice (first at line 3)"},
        {header("uniform float x < ui_min = 2;\n ui_max = 1; > = 1.5;\n"), 4, "ui_min 2 must be below ui_max 1"},
        {header("uniform float x < ui_min = -1e999; ui_max = 1; > = 0;\n"), 3, "ui_min must be finite"},
        {header("uniform float x < " + kRange + " ui_step = 1e999; > = 0;\n"), 3, "ui_step must be finite"},
        {header("uniform float x < " + kRange + "\n> = 5;\n"), 4, "default 5 is outside [0, 1]"},
        {header("uniform float x < " + kRange + " ui_step = 0; > = 0;\n"), 3, "ui_step must be above 0"},
        {header("uniform float x < ui_min = 0; ui_max = 2e9; > = 0;\n"), 3, "ui_max must be within +-1e9"},
        {header("uniform float x < ui_min = 0; > = 0;\n"), 3, "float parameter 'x': needs ui_min and ui_max"},
        {header("uniform float x < " + kRange + " > = true;\n"), 3, "float parameter 'x': the default must be a number"},
        {header("uniform float x < ui_min = \"0\"; ui_max = 1; > = 0;\n"), 3, "ui_min must be a number"},
        {header("uniform float x < ui_min = 1.2.3; ui_max = 1; > = 0;\n"), 3, "malformed number '1.2.3'"},
        {header("uniform float x < ui_type = \"color\"; " + kRange + " > = 0;\n"), 3,
         "ui_type 'color' is not one of slider, drag, input"},
        {header("uniform int n < ui_min = 0.5; ui_max = 4; > = 1;\n"), 3, "int parameter 'n': ui_min must be a whole number"},
        {header("uniform int n < ui_min = 0; ui_max = 4; > = 2.0;\n"), 3, "int parameter 'n': the default must be a whole number"},
        {header("uniform int n < ui_min = 0; ui_max = 2000000; > = 1;\n"), 3, "ui_max must be within +-1e6"},
        {header("uniform int n < ui_type = \"combo\"; " + kRange + " > = 0;\n"), 3, "ui_type 'combo' needs ui_items"},
        {header("uniform int n < ui_items = \"a\\0b\"; > = 0;\n"), 3, "ui_items needs ui_type combo, radio or list"},
        {header("uniform float x < ui_type = \"combo\"; ui_items = \"a\\0b\"; > = 0;\n"), 3, "ui_type 'combo' is not one of slider"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"" + items(17) + "\"; > = 0;\n"), 3, "17 items; 1 to 16 allowed"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"\"; > = 0;\n"), 3, "0 items; 1 to 16 allowed"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"a\\0\\0b\"; > = 0;\n"), 3, "item 2 is empty"},
        {header("uniform int e < ui_type = \"list\"; ui_items = \"" + std::string(33, 'a') + "\"; > = 0;\n"), 3,
         "item 1 has 33 characters; at most 32"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"a\\0b\\0a\"; > = 0;\n"), 3, "item 'a' is listed twice"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"a b\\0a-b\"; > = 0;\n"), 3,
         "items 'a b' and 'a-b' both #define E_A_B"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"+\"; > = 0;\n"), 3, "item '+' has no letter or digit"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"a\\0b\\0c\"; >\n = 3;\n"), 4, "default 3 is not an item's index (0 to 2)"},
        {header("uniform int e < ui_type = \"combo\"; ui_items = \"a\\0b\";\n ui_min = 0; > = 0;\n"), 4,
         "ui_min does not apply to an enum"},
        {header("uniform int a_b < ui_type = \"combo\"; ui_items = \"c\"; > = 0;\n"
                "uniform int a < ui_type = \"combo\"; ui_items = \"b c\"; > = 0;\n"), 4, "#define A_B_C is already"},
        {header("uniform int gl < ui_type = \"combo\"; ui_items = \"es\"; > = 0;\n"), 3, "#define GL_ES would begin with GL_"},
        {header("uniform bool b < " + kRange + " > = true;\n"), 3, "ui_min does not apply to a bool"},
        {header("uniform bool b < ui_type = \"slider\"; > = true;\n"), 3, "ui_type 'slider' is not one of checkbox"},
        {header("uniform bool b = 1;\n"), 3, "bool parameter 'b': the default must be true or false"},
        {header("label = \"" + std::string(49, 'x') + "\";\n"), 3, "label has 49 characters; at most 48"},
        {header("label = \"\";\n"), 3, "label is empty"},
        {header("summary = \"" + std::string(161, 'x') + "\";\n"), 3, "summary has 161 characters; at most 160"},
        {header("uniform bool b < ui_label = \"" + std::string(49, 'x') + "\"; > = true;\n"), 3, "ui_label has 49 characters; at most 48"},
        {header("uniform bool b < ui_tooltip = \"" + std::string(201, 'x') + "\"; > = true;\n"), 3, "ui_tooltip has 201 characters; at most 200"},
        {header("uniform float x < " + kRange + " ui_units = \"" + std::string(17, 'x') + "\"; > = 0;\n"), 3,
         "ui_units has 17 characters; at most 16"},
        {header("label = \"a\tb\";\n"), 3, "byte 0x09 in a string: only printable ASCII"},
        {header("label = \"caf\xc3\xa9\";\n"), 3, "byte 0xc3 in a string: only printable ASCII"},
        {header("label = \"a\\0b\";\n"), 3, "\\0 is only allowed in ui_items"},
        {header("\n\nlabel = \"a\\nb\";\n"), 5, "unknown escape \\n"},
        {header("uniform bool b = true;\x01\n"), 3, "byte 0x01 is not allowed in the header"},
        {header("uniform bool b = true; @\n"), 3, "unexpected '@'"},
        {header("uniform bool b\n"), 3, "parameter 'b' has no default"},
        {header("uniform float x ui_min = 0;\n"), 3, "expected '<' or '=' after parameter 'x'"},
    };
}
} // namespace

TEST(UserHeader, EveryBadHeaderIsOneLineWithTheLineOfItsFault) {
    const std::vector<Bad> bad = badHeaders();
    ASSERT_GE(bad.size(), 30u);
    for (size_t i = 0; i < bad.size(); ++i) {
        SCOPED_TRACE("case " + std::to_string(i) + ": " + bad[i].message);
        const std::string msg = errorOf([&] { parse(bad[i].text); });
        const std::string where = kFile + ":" + std::to_string(bad[i].line) + ": ";
        EXPECT_EQ(msg.rfind(where, 0), 0u) << msg;
        EXPECT_NE(msg.find(bad[i].message), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
}

TEST(UserHeader, TheNameComesFromTheFileAndIsNoBuiltInTechnique) {
    const auto ids = builtinIds();
    EXPECT_EQ(userTechniqueName("dir/sub/my_ao2.ao.glsl", ids), "my_ao2");
    EXPECT_EQ(userTechniqueName("x.ao.glsl", ids), "x");
    EXPECT_EQ(userTechniqueName(std::string(24, 'a') + ".ao.glsl", ids), std::string(24, 'a'));
    const std::pair<std::string, std::string> bad[] = {
        {"dir/My.ao.glsl", "[a-z][a-z0-9_]{0,23}"},       {"1x.ao.glsl", "[a-z][a-z0-9_]{0,23}"},
        {"a-b.ao.glsl", "[a-z][a-z0-9_]{0,23}"},          {".ao.glsl", "[a-z][a-z0-9_]{0,23}"},
        {std::string(25, 'a') + ".ao.glsl", "[a-z][a-z0-9_]{0,23}"},
        {"x.glsl", "is named NAME.ao.glsl"},              {"x.ao.glsl.txt", "is named NAME.ao.glsl"},
        {"dir.ao.glsl/", "is named NAME.ao.glsl"},
    };
    for (const auto& [path, message] : bad) {
        const std::string msg = errorOf([&] { userTechniqueName(path, ids); });
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find(message), std::string::npos) << msg;
    }
    for (const auto& id : ids) {
        const std::string msg = errorOf([&] { userTechniqueName("d/" + id + ".ao.glsl", ids); });
        EXPECT_NE(msg.find("'" + id + "' is a built-in technique"), std::string::npos) << msg;
    }
    // parseUserHeader takes its name from the same rule.
    const std::string msg = errorOf([&] { parseUserHeader("/*ssaolab interface = 1; */", "Bad.ao.glsl", ids); });
    EXPECT_EQ(msg.rfind("Bad.ao.glsl: ", 0), 0u) << msg;
}

namespace {
// glslangValidator's output on a fragment shader, "" when it compiles.
std::string glslangErrors(const std::string& source, const std::string& name) {
    const std::string path = ssaotest::writeTemp("user_header_" + name + ".frag", source);
    const ProgramRun r = runProgram({"glslangValidator", "-S", "frag", path}, ChildStream::Capture, ChildStream::Capture);
    if (!r.started) return "glslangValidator did not start: .ci/install-deps.sh installs glslang-tools";
    return r.exitCode == 0 ? "" : r.out;
}
} // namespace

TEST(UserHeader, GeneratedGlslIsAStd140BlockEnumDefinesAndALineReset) {
    const std::string glsl = userParamsGlsl(parse(kValid), 3);
    EXPECT_NE(glsl.find("layout(std140, binding = 3) uniform SsaoUserParams {"), std::string::npos) << glsl;
    for (const char* member : {"float radius_scale;", "int samples;", "int use_normals;", "int falloff;", "float bias;"})
        EXPECT_NE(glsl.find(member), std::string::npos) << member;
    for (const char* define : {"#define FALLOFF_NONE 0\n", "#define FALLOFF_LINEAR 1\n", "#define FALLOFF_SMOOTH 2\n",
                               "#define SHAPE_NO_FALLOFF 0\n", "#define SHAPE_1_R_2 1\n", "#define SHAPE_LINEAR 2\n"})
        EXPECT_NE(glsl.find(define), std::string::npos) << define;
    const std::string tail = "\n#line 1\n";
    ASSERT_GE(glsl.size(), tail.size());
    EXPECT_EQ(glsl.substr(glsl.size() - tail.size()), tail);
    EXPECT_NE(userParamsGlsl(parse(header("")), 0).find("int ssao_no_params;"), std::string::npos);
    EXPECT_THROW(userParamsGlsl(parse(kValid), -1), Error);
}

TEST(UserHeader, GeneratedGlslCompilesAndKeepsTheFilesLineNumbers) {
    EXPECT_EQ(glslangErrors("#version 450\n" + userParamsGlsl(parse(kValid), 3) + kValid, "valid"), "");
    const std::string none = header("");
    EXPECT_EQ(glslangErrors("#version 450\n" + userParamsGlsl(parse(none), 0) + none, "no_params"), "");
    const std::string trivial = "#version 450\n" + userParamsGlsl(parse(kValid), 3) + "void main() {}\n";
    EXPECT_EQ(glslangErrors(trivial, "trivial"), "");
    // The edges of the naming rules: a name of one '_', trailing and leading '_', items that are
    // digits or punctuation around words, the longest names.
    const std::string edges = header("uniform int _ < ui_type = \"combo\"; ui_items = \"1\\0x y\\0-x-\"; > = 0;\n"
                                     "uniform float x_ < " + kRange + " > = 0;\n"
                                     "uniform int _a9 < ui_type = \"list\"; ui_items = \"" + std::string(32, 'q') + "\"; > = 0;\n"
                                     "uniform bool " + std::string(32, 'z') + " = true;\n");
    const std::string edgesGlsl = userParamsGlsl(parse(edges), 0);
    EXPECT_NE(edgesGlsl.find("#define _X_Y 1\n"), std::string::npos) << edgesGlsl;
    EXPECT_EQ(glslangErrors("#version 450\n" + edgesGlsl + edges, "edges"), "");
    // A fault on the body's line 19 is reported on line 19.
    const std::string broken = kValid + "not glsl;\n";
    const std::string log = glslangErrors("#version 450\n" + userParamsGlsl(parse(broken), 3) + broken, "broken");
    EXPECT_NE(log.find("0:19:"), std::string::npos) << log;
}

TEST(UserHeader, PackingPutsEachValueAtItsOffset) {
    const UserHeader h = parse(kValid); // float, int, bool, enum, float, enum
    std::vector<unsigned char> b = packUserParams(h, {1.5, 7, 1, 2, -0.0075, 0});
    ASSERT_EQ(b.size(), 32u); // 24 bytes rounded up to 16
    auto f = [&](size_t at) { float v; std::memcpy(&v, &b[at], 4); return v; };
    auto i = [&](size_t at) { std::int32_t v; std::memcpy(&v, &b[at], 4); return v; };
    EXPECT_EQ(f(0), 1.5f);
    EXPECT_EQ(i(4), 7);
    EXPECT_EQ(i(8), 1);
    EXPECT_EQ(i(12), 2);
    EXPECT_EQ(f(16), -0.0075f);
    EXPECT_EQ(i(20), 0);
    EXPECT_EQ(i(24), 0);
    EXPECT_EQ(i(28), 0);
    b = packUserParams(h, {0.25, 64, 0, 0, 25, 1});
    EXPECT_EQ(i(4), 64);
    EXPECT_EQ(i(8), 0);
    EXPECT_EQ(f(16), 25.0f);
    EXPECT_EQ(i(20), 1);
    b = packUserParams(parse(header(params(4))), {1, 0, 1, 1});
    ASSERT_EQ(b.size(), 16u);
    EXPECT_EQ(i(0), 1);
    EXPECT_EQ(i(4), 0);
    EXPECT_EQ(i(12), 1);
    EXPECT_EQ(packUserParams(parse(header("")), {}), std::vector<unsigned char>(16, 0));
}

TEST(UserHeader, PackingRefusesWhatTheBlockCannotHold) {
    const UserHeader h = parse(kValid);
    EXPECT_NE(errorOf([&] { packUserParams(h, {1, 2}); }).find("6 parameters, 2 values"), std::string::npos);
    EXPECT_NE(errorOf([&] { packUserParams(h, {1, 65, 1, 2, 0, 0}); }).find("samples"), std::string::npos);
    EXPECT_NE(errorOf([&] { packUserParams(h, {1, 2.5, 1, 2, 0, 0}); }).find("whole"), std::string::npos);
    EXPECT_NE(errorOf([&] { packUserParams(h, {std::nan(""), 2, 1, 2, 0, 0}); }).find("finite"), std::string::npos);
    EXPECT_NE(errorOf([&] { packUserParams(h, {1, 2, 1, 3, 0, 0}); }).find("falloff"), std::string::npos);
}

TEST(UserHeader, TheHashIsFnv1a64AndChangesWithOneByte) {
    EXPECT_EQ(userTechniqueHash(""), "cbf29ce484222325");
    EXPECT_EQ(userTechniqueHash("a"), "af63dc4c8601ec8c");
    const std::string base = userTechniqueHash(kValid);
    EXPECT_EQ(base.size(), 16u);
    EXPECT_EQ(userTechniqueHash(kValid), base);
    for (size_t at = 0; at < kValid.size(); ++at) {
        std::string t = kValid;
        t[at] = char(t[at] ^ 1);
        EXPECT_NE(userTechniqueHash(t), base) << at;
    }
    EXPECT_NE(userTechniqueHash(kValid + " "), base);
}
