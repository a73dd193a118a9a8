// What a new user hit in the CLI and the window, each fixed and kept fixed.
#include "base/image.h"
#include "cli_run.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace ssaotest;

TEST(CliNewUser, HelpSaysTheDepthDefaultIsReversedZ) {
    for (const char* cmd : {"render --help", "view --help"}) {
        const CliRun r = ssaolab(cmd);
        ASSERT_EQ(r.exitCode, 0) << cmd;
        EXPECT_NE(r.out.find("reversed (default"), std::string::npos) << cmd << "\n" << r.out;
        EXPECT_EQ(r.out.find("standard (default"), std::string::npos) << cmd;
    }
}

TEST(CliNewUser, AMistypedOptionOrCommandNamesTheClosestAndItsHelp) {
    // Was: "The following arguments were not expected: F --scnee", pointing at ssaolab --help.
    expectCleanFailure(ssaolab("render --scnee builtin:corner"),
                       "render: unknown option '--scnee' (did you mean --scene?) (see ssaolab render --help)");
    // Was not called an unknown command at all.
    expectCleanFailure(ssaolab("rendr --scene builtin:corner"), "unknown command 'rendr' (did you mean render?)");
    expectCleanFailure(ssaolab("bench merge --outt x"), "bench merge: unknown option '--outt' (did you mean --out?) "
                                                        "(see ssaolab bench merge --help)");
    expectCleanFailure(ssaolab("bench mrege"), "did you mean merge?");
}

TEST(CliNewUser, TheReferencePreviewDrawsTheSkyLikeTheAo) {
    // ao_reference.png drew the sky white like open AO, so silhouettes against it vanished.
    const std::string out = outDir("sky");
    std::filesystem::remove_all(out);
    const CliRun r = ssaolab("render --scene builtin:showcase --size 160x90 --timing-frames 1 --reference "
                             "--reference-rays 8 --quiet --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ssao::Image ref = ssao::readPng(out + "/ao_reference.png");
    const ssao::Image ao = ssao::readPng(out + "/ao.denoised.png");
    const ssao::Image depth = ssao::readExr(out + "/gbuffer.depth.exr");
    int sky = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            if (depth.at(x, y) <= 0.0f) {
                ++sky;
                EXPECT_NEAR(ref.at(x, y), ao.at(x, y, 0), 1.0f / 255.0f) << x << "," << y;
                EXPECT_LT(ref.at(x, y), 0.5f) << "sky drawn like open AO at " << x << "," << y;
            }
    EXPECT_GT(sky, 100) << "the showcase view has sky at the top";
}

TEST(CliNewUser, TheWindowSaysOnStderrWhatItCouldNotOpen) {
    // view --scene /nonexistent.gltf opened on the built-in scene with the error in the window, but
    // printed nothing and exited 0.
    for (const std::string& args : {std::string("--scene /nonexistent.gltf"), std::string("--preset no-such-preset")}) {
        const std::string log = std::string(SSAOLAB_TEST_TMP) + "/xvfb_bad.err";
        const std::string cmd = "'" + std::string(SSAOLAB_BINARY) + "' view --size 800x500 --frames 2 " + args +
                                " >/dev/null 2>" + log;
        EXPECT_EQ(underXvfb(cmd, "bad"), 1) << args;
        const std::string err = slurp(log);
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
        EXPECT_NE(err.find("ssaolab: error: "), std::string::npos) << err;
        EXPECT_NE(err.find(args.substr(args.find(' ') + 1)), std::string::npos) << err;
        EXPECT_NE(err.find("(showing builtin:showcase)"), std::string::npos) << err;
    }
}
