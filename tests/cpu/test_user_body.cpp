// A user technique's body is checked on its tokens before any compiler sees it (user_source.h
// checkUserBody): the bombs that crashed the driver's compiler or took it past 3 GiB - a 200 KiB
// expression, a #define doubling chain, a local array of 10^8 floats, #line pointing errors at
// ssaolab's own files - are each one "FILE:LINE: why", found in milliseconds; ordinary shaders pass.
#include "techniques/user/user_source.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace {

// The error checkUserBody gives `body`, "" when it passes.
std::string refusal(const std::string& body) {
    try {
        ssao::checkUserBody(body, "t.ao.glsl");
    } catch (const ssao::Error& e) {
        return e.what();
    }
    return "";
}

std::string repeated(const std::string& piece, int n, const std::string& sep) {
    std::string s;
    for (int i = 0; i < n; ++i)
        s += (i ? sep : "") + piece;
    return s;
}

void expectRefused(const std::string& body, const std::string& where, const std::string& why) {
    const auto start = std::chrono::steady_clock::now();
    const std::string e = refusal(body);
    EXPECT_EQ(e.rfind(where, 0), 0u) << e;
    EXPECT_NE(e.find(why), std::string::npos) << e;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0) << why;
}

} // namespace

TEST(UserBody, OrdinaryShadersPass) {
    EXPECT_EQ(refusal("#define PI 3.14159265\n#define SAT(x) clamp((x), 0.0, 1.0)\nconst int N = 16;\n"
                      "float w[N * 4];\nfloat ssaoUserAo() {\n  float s = 0.0;\n"
                      "  for (int i = 0; i < N; ++i) s += w[i] * SAT(float(i) / PI);\n#ifdef AO_POWER_ONE\n"
                      "  s *= 1.0;\n#endif\n  return SAT(s);\n}\n"),
              "");
    EXPECT_EQ(refusal("#define X X + 1\n#define A B\n#define B A\nfloat f() { return X + A; }\n"), "") // recursion stops
        << "a macro is not expanded inside itself";
    EXPECT_EQ(refusal("float k[4096];\nfloat g(int i) { return k[i + 100000]; }\n"), "") << "an index is no size";
}

TEST(UserBody, AHugeExpressionIsRefusedBeforeTheCompilerRecursesOnIt) {
    // 100 000 terms: the driver's compiler crashed with SIGSEGV (its stack) past about 16 000.
    expectRefused("float f() {\n  float k = 0.5;\n  return " + repeated("k", 100000, "+") + ";\n}\n", "t.ao.glsl:3:",
                  "a statement of more than 8192 tokens");
    expectRefused("#define K " + repeated("k", 3000, "+") + "\nfloat f(float k) {\n  return K + K + K;\n}\n", "t.ao.glsl:3:",
                  "macros expanded");
}

TEST(UserBody, MacroExpansionIsMeasuredNotExpanded) {
    std::string chain = "#define A0 k\n";
    for (int i = 1; i <= 60; ++i)
        chain += "#define A" + std::to_string(i) + " (A" + std::to_string(i - 1) + " + A" + std::to_string(i - 1) + ")\n";
    expectRefused(chain + "float f(float k) { return A60; }\n", "t.ao.glsl:62:", "expand");
    // Empty macros add no token, only work: the budget counts steps too.
    std::string empty = "#define E0\n";
    for (int i = 1; i <= 60; ++i)
        empty += "#define E" + std::to_string(i) + " E" + std::to_string(i - 1) + " E" + std::to_string(i - 1) + "\n";
    expectRefused(empty + "float f() { E60 return 1.0; }\n", "t.ao.glsl:62:", "steps");
    // A function-like macro doubling its argument, nested.
    expectRefused("#define D(x) x x\nfloat f() { return " + repeated("D(", 40, "") + "1.0" + std::string(40, ')') + "; }\n",
                  "t.ao.glsl:2:", "expand");
}

TEST(UserBody, ArraysOfAConstantSizeAreBounded) {
    expectRefused("float f() {\n  float a[100000000];\n  return a[0];\n}\n", "t.ao.glsl:2:", "an array of 100000000 elements");
    expectRefused("const int N = 5000;\nfloat a[N];\n", "t.ao.glsl:2:", "5000 elements");
    expectRefused("#define N 64\nfloat a[N][N + 1];\n", "t.ao.glsl:2:", "4160 elements");
    expectRefused("float a[int(1e8)];\n", "t.ao.glsl:1:", "elements");
    EXPECT_EQ(refusal("float a[64][64];\n"), "");
}

TEST(UserBody, NestingIsBoundedThroughMacrosToo) {
    expectRefused("float f() { return " + std::string(100, '(') + "1.0" + std::string(100, ')') + "; }\n", "t.ao.glsl:1:",
                  "nest deeper than 64");
    std::string chain = "#define P0 (1.0)\n";
    for (int i = 1; i <= 80; ++i)
        chain += "#define P" + std::to_string(i) + " (P" + std::to_string(i - 1) + ")\n";
    expectRefused(chain + "float f() { return P80; }\n", "t.ao.glsl:82:", "nest deeper than 64");
    expectRefused("#define OPEN (\nfloat f() { return OPEN 1.0); }\n", "t.ao.glsl:1:", "close every bracket");
}

TEST(UserBody, DirectivesThatRedirectOrReconfigureTheCompilerAreRefusedByLine) {
    expectRefused("float f() { return 1.0; }\n#line 5 1\n", "t.ao.glsl:2:", "#line is not available");
    expectRefused("\n\n  #  extension GL_ARB_gpu_shader_int64 : enable\n", "t.ao.glsl:3:", "#extension is not available");
    expectRefused("#version 460\n", "t.ao.glsl:1:", "#version is not available");
    expectRefused("#include \"x.glsl\"\n", "t.ao.glsl:1:", "#include is not available");
    expectRefused("#define CAT(a, b) a ## b\n", "t.ao.glsl:1:", "token pasting");
    expectRefused("/* a comment\nover lines */ float x;\n#define \\\n  Y 1\n#line 9\n", "t.ao.glsl:5:", "#line");
}

TEST(UserBody, TheCheckerItselfRecursesOnlyBoundedlyDeep) {
    // 20 000 chained macros, and a call nested 20 000 times in its own argument: refused by line
    // before the checker's own recursion could run out of stack.
    std::string chain = "#define M0 1.0\n";
    for (int i = 1; i < 20000; ++i)
        chain += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + "\n";
    expectRefused(chain + "float f() { return M19999; }\n", "t.ao.glsl:20001:", "levels deep");
    expectRefused("#define F(x) x\nfloat f() { return " + repeated("F(", 20000, "") + "1.0" + std::string(20000, ')') + "; }\n",
                  "t.ao.glsl:2:", "levels deep");
}

TEST(UserBody, WhatThePreprocessorSeesIsWhatIsChecked) {
    // Lines are spliced before comments end, as GLSL reads them: a comment closed by "*\<newline>/"
    // hides nothing.
    expectRefused("/* x *\\\n/\n#line 5\n", "t.ao.glsl:3:", "#line is not available");
    // An #include inside a comment is still a line the shader library would inline.
    expectRefused("/*\n#include \"../../etc/passwd\"\n*/\n", "t.ao.glsl:2:", "#include is not available");
    // A function-like macro whose name is also a part of the word "define".
    expectRefused("#define f(x) x + x + x + x\nfloat g() { return " + repeated("f(", 15, "") + "0.1" + std::string(15, ')') +
                      "; }\n",
                  "t.ao.glsl:2:", "expand");
    // #if is not evaluated: every definition a name was given may apply, #undef forgets nothing.
    expectRefused("#define K " + repeated("k", 3000, "+") + "\n#if 0\n#undef K\n#define K 1\n#endif\n"
                  "float g(float k) { return K + K + K; }\n",
                  "t.ao.glsl:6:", "macros expanded");
    // A stray ')' in a branch that is not compiled does not lift the nesting bound.
    expectRefused("#if 0\n" + std::string(100, ')') + "\n#endif\nfloat g() { return " + std::string(100, '(') + "1.0" +
                      std::string(100, ')') + "; }\n",
                  "t.ao.glsl:4:", "nest deeper than 64");
    // An unsigned size: -1u is 4294967295.
    expectRefused("float a[-1u];\n", "t.ao.glsl:1:", "an array of 4.2949673e+09 elements");
}

TEST(UserBody, ConstantsAreEvaluatedWithinTheSameBounds) {
    // 200 000 signs, and a 623-byte doubling chain evaluated as an array's size: each once crashed
    // (the checker's own stack) or hung the checker.
    expectRefused("float w[" + std::string(200000, '-') + "1];\n", "t.ao.glsl:1:", "levels deep");
    std::string chain = "#define M0 1\n";
    for (int k = 1; k <= 14; ++k)
        chain += "#define M" + std::to_string(k) + " (" + repeated("M" + std::to_string(k - 1), 8, "+") + ")\n";
    expectRefused(chain + "float w[M14];\n", "t.ao.glsl:16:", "steps");
}
