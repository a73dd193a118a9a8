// A user technique in the explorer (app/view/live/technique_watch.h): its rows are widgets like the
// built-ins'; a new version of its file is probed in a child process and adopted only when it
// passed; a compile error or a shader that never ends is named (FILE:LINE, or the time limit)
// while the last good version keeps running.
#include "gl/readback.h"
#include "gl_fixture.h"
#include "ui_driver.h"

#include "settings/params.h"
#include "techniques/technique.h"
#include "techniques/user/user_folder.h"
#include "test_util.h"

#include <chrono>
#include <filesystem>
#include <thread>

using namespace ssao;
using namespace ssaotest;
namespace fs = std::filesystem;

namespace {

// AO = the parameter `value` on every geometry pixel (line 6 is the body's return).
std::string flat(const std::string& body) {
    return "/*ssaolab\ninterface = 1;\n"
           "uniform float value < ui_min = 0.0; ui_max = 1.0; ui_label = \"Value\"; ui_tooltip = \"The AO.\"; > = 0.5;\n"
           "*/\nfloat ssaoUserAo() {\n" +
           body + "\n}\n";
}

class AppUserTechnique : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        // Per test: ctest runs these tests at the same time, and each edits its folder's file.
        const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        dir_ = std::string(SSAOLAB_TEST_TMP) + "/app_techniques_" + name;
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        write(flat("    return value;"));
        setUserTechniques(scanUserTechniques(dir_, true).loaded);
        AppOptions o;
        o.userPresetDir = dir_ + "_presets";
        o.techniqueDir = dir_;
        o.probeProgram = SSAOLAB_BINARY;
        o.renderScale = 0.3f;
        o.reference = false;
        ui_ = std::make_unique<UiDriver>(o);
        setParam(ui_->app().settings(), "ao.technique", "user.flat");
        setParam(ui_->app().settings(), "denoise.kind", "none");
        ui_->frames(2);
    }
    void TearDown() override {
        ui_.reset();
        setUserTechniques({});
        GlTest::TearDown();
    }
    void write(const std::string& text) { writeFileAtomicallyForTest(dir_ + "/flat.ao.glsl", text); }
    static void writeFileAtomicallyForTest(const std::string& path, const std::string& text) {
        const std::string tmp = path + ".tmp";
        writeTemp(fs::relative(tmp, SSAOLAB_TEST_TMP).string(), text);
        fs::rename(tmp, path);
    }
    // Polls as the window does until the watch has adopted or refused the new version.
    void awaitVerdict() {
        const unsigned before = ui_->app().techniqueVerdicts();
        for (int i = 0; i < 1200 && ui_->app().techniqueVerdicts() == before; ++i) {
            ui_->app().pollShaderReload();
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        ui_->frames(2);
    }
    // The AO of the pixels that hold geometry.
    double meanAo() {
        Image mask = readBack(ui_->app().renderer().texture("gbuffer.position"), 4).channel(3);
        return stats(readBack(ui_->app().renderer().texture("ao.raw"), 1), &mask).mean;
    }
    std::string dir_;
    std::unique_ptr<UiDriver> ui_;
};

} // namespace

TEST_F(AppUserTechnique, ItsRowsAreWidgetsAndItsValueReachesTheShader) {
    EXPECT_NEAR(meanAo(), 0.5, 1e-6);
    ASSERT_TRUE(ui_->has("user.flat.value"));
    setParam(ui_->app().settings(), "user.flat.value", "0.2");
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.2, 1e-6);
    ui_->click("user.flat.value#reset");
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.5, 1e-6);
}

TEST_F(AppUserTechnique, ACompileErrorIsNamedAndTheLastGoodVersionKeepsRunning) {
    write(flat("    return value * undeclared_thing;")); // line 6
    awaitVerdict();
    const std::string error = ui_->app().frames().shaderError();
    std::printf("%s\n", error.c_str());
    EXPECT_NE(error.find(dir_ + "/flat.ao.glsl:6:"), std::string::npos) << error;
    EXPECT_NE(error.find("undeclared_thing"), std::string::npos) << error;
    EXPECT_NE(error.find("the last good version keeps running"), std::string::npos) << error;
    EXPECT_TRUE(ui_->app().statusIsError());
    ui_->app().renderer().invalidate();
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.5, 1e-6); // the last good program

    write(flat("    return value * 0.5;")); // fixed: adopted, the error clears
    awaitVerdict();
    EXPECT_TRUE(ui_->app().frames().shaderError().empty()) << ui_->app().frames().shaderError();
    EXPECT_NE(ui_->app().status().find("new version running: user.flat"), std::string::npos) << ui_->app().status();
    EXPECT_NEAR(meanAo(), 0.25, 1e-6);
}

TEST_F(AppUserTechnique, AShaderThatNeverEndsIsRefusedByItsProbeAndTheExplorerGoesOn) {
    std::string endless = "    float x = 0.0;\n    for (int i = 0; i >= 0; i += int(ssaoRadius() > -1.0)) {\n";
    for (int step = 0; step < 64; ++step)
        endless += "        x = sin(x * 1.3 + float(i));\n";
    write(flat(endless + "    }\n    return x;"));
    awaitVerdict();
    const std::string error = ui_->app().frames().shaderError();
    std::printf("%s\n", error.c_str());
    EXPECT_NE(error.find("a frame took longer than"), std::string::npos) << error;
    EXPECT_NE(error.find("flat.ao.glsl"), std::string::npos) << error;
    ui_->app().renderer().invalidate();
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.5, 1e-6);
}

TEST_F(AppUserTechnique, ANewHeaderIsAdoptedAndTheValuesFitItsRanges) {
    setParam(ui_->app().settings(), "user.flat.value", "0.9");
    ui_->frames(1);
    write("/*ssaolab\ninterface = 1;\n"
          "uniform float value < ui_min = 0.0; ui_max = 0.4; > = 0.3;\n"
          "uniform bool invert < ui_label = \"Invert\"; > = false;\n"
          "*/\nfloat ssaoUserAo() {\n    return invert != 0 ? 1.0 - value : value;\n}\n");
    awaitVerdict();
    ASSERT_NE(findParam("user.flat.invert"), nullptr);
    EXPECT_EQ(findParam("user.flat.value")->max, 0.4);
    EXPECT_NEAR(meanAo(), 0.4, 1e-6); // 0.9 brought into the new range
    ASSERT_TRUE(ui_->has("user.flat.invert"));
    ui_->click("user.flat.invert");
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.6, 1e-6);
}

TEST_F(AppUserTechnique, TheProbeRendersAtTheExplorersSizeSoAShaderTooSlowThereIsRefused) {
    // Endless only on frames wider than 100 pixels: a probe of a small frame would pass it, and the
    // explorer's own frames would then stall. The probe renders at the explorer's size instead.
    ASSERT_GT(ui_->app().renderer().width(), 100);
    std::string body = "    if (ssaoFrameSize().x <= 100.0) return value;\n"
                       "    float x = 0.0;\n    for (int i = 0; i >= 0; i += int(ssaoRadius() > -1.0)) {\n";
    for (int step = 0; step < 64; ++step)
        body += "        x = sin(x * 1.3 + float(i));\n";
    write(flat(body + "    }\n    return x;"));
    awaitVerdict();
    const std::string error = ui_->app().frames().shaderError();
    std::printf("%s\n", error.c_str());
    EXPECT_NE(error.find("a frame took longer than"), std::string::npos) << error;
    ui_->app().renderer().invalidate();
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.5, 1e-6); // the last good version
}

TEST_F(AppUserTechnique, AVersionWhoseFileBecomesALinkWhileItIsProbedIsDropped) {
    // The probe tests the bytes checked here, never the path again: a link swapped in meanwhile -
    // even to a file outside the folder holding the very same text - is not followed, and the
    // version it replaced is not adopted.
    const std::string outside = std::string(SSAOLAB_TEST_TMP) + "/app_techniques_outside.ao.glsl";
    writeTemp("app_techniques_outside.ao.glsl", flat("    return value * 0.5;"));
    write(flat("    return value * 0.5;"));
    ui_->app().pollShaderReload(); // read, checked and handed to its probe
    fs::remove(dir_ + "/flat.ao.glsl");
    fs::create_symlink(outside, dir_ + "/flat.ao.glsl");
    awaitVerdict();
    const std::string error = ui_->app().frames().shaderError();
    EXPECT_NE(error.find("changed while it was probed"), std::string::npos) << error;
    EXPECT_EQ(ui_->app().status().find("new version running"), std::string::npos) << ui_->app().status();
    for (int i = 0; i < 10; ++i) { // later scans: the link is never read, nothing else is adopted
        ui_->app().pollShaderReload();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ui_->app().renderer().invalidate();
    ui_->frames(2);
    EXPECT_NEAR(meanAo(), 0.5, 1e-6); // the first version still runs
}
