#include "gl/shader_library.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace ssao;

namespace {
// One folder per test: ctest runs the tests of this file in parallel processes, and a shared folder
// let one test truncate main.frag while another read it (a flaky "must start with #version").
std::string makeDir() {
    std::string dir = std::string(SSAOLAB_TEST_TMP) + "/shaders_" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::create_directories(dir + "/include");
    std::ofstream(dir + "/include/a.glsl") << "float a() { return 1.0; }\n";
    std::ofstream(dir + "/main.frag") << "#version 450 core\n// comment\n#include "
                                         "\"include/a.glsl\"\n#include \"include/a.glsl\"\nvoid main() {}\n";
    std::ofstream(dir + "/noversion.frag") << "void main() {}\n";
    return dir;
}
} // namespace

TEST(ShaderText, IncludesOnceInjectsDefinesAndKeepsLineNumbers) {
    std::string dir = makeDir();
    std::vector<std::string> files;
    std::string out = gl::preprocessShader(dir, "main.frag", {{"FOO", "3"}}, files);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0], "main.frag");
    EXPECT_EQ(files[1], "include/a.glsl");
    EXPECT_EQ(out.rfind("#version 450 core\n#define FOO 3\n#line 2 0\n", 0), 0u) << out;
    EXPECT_NE(out.find("#line 1 1\nfloat a()"), std::string::npos) << out;
    EXPECT_NE(out.find("#line 4 0\n"), std::string::npos) << out; // back in main.frag after the include
    // included once although #included twice
    EXPECT_EQ(out.find("float a()"), out.rfind("float a()"));
}

TEST(ShaderText, MissingFilesAndVersionAreErrors) {
    std::string dir = makeDir();
    std::vector<std::string> files;
    EXPECT_THROW(gl::preprocessShader(dir, "nope.frag", {}, files), Error);
    EXPECT_THROW(gl::preprocessShader(dir, "noversion.frag", {}, files), Error);
}

TEST(ShaderText, DriverLogsAreMappedToFileAndLine) {
    std::vector<std::string> files = {"techniques/kernel/kernel.frag", "include/onb.glsl"};
    EXPECT_EQ(gl::mapLogToFiles("1:12(3): error: bad", files), "shaders/include/onb.glsl:12: error: bad\n");
    EXPECT_EQ(gl::mapLogToFiles("0(7) : error C0000: x", files),
              "shaders/techniques/kernel/kernel.frag:7 : error C0000: x\n");
}

TEST(ShaderText, ASourceGivenAsTextIsReadUnderItsNameWithIncludesFromTheFolder) {
    std::string dir = makeDir();
    const gl::Sources sources{{"mine/x.ao.glsl", "#version 450 core\n#include \"include/a.glsl\"\nvoid main() {}\n"},
                              {"main.frag", "#version 450 core\n// text wins over the file\n"}};
    std::vector<std::string> files;
    const std::string out = gl::preprocessShader(dir, "mine/x.ao.glsl", {}, files, &sources);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0], "mine/x.ao.glsl");
    EXPECT_NE(out.find("float a()"), std::string::npos) << out;
    EXPECT_NE(gl::preprocessShader(dir, "main.frag", {}, files, &sources).find("text wins"), std::string::npos);
    const gl::Sources bad{{"mine/y.ao.glsl", "void main() {}\n"}};
    try {
        gl::preprocessShader(dir, "mine/y.ao.glsl", {}, files, &bad);
        FAIL() << "no #version accepted";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("mine/y.ao.glsl:1: ", 0), 0u) << e.what(); // its name, not the folder's
    }
}
