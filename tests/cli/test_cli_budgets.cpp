// Whole program on input that would cost without bound: images given to --score and the screen-space
// oracle's G-buffer are budgeted before anything is read, decoded or allocated; each refusal is one
// line naming the budget and the option that changes it.
#include "base/image.h"
#include "cli_run.h"

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>

using namespace ssaotest;

namespace {
const std::string kView = "render --scene builtin:corner --size 64x36 --timing-frames 1 --reference --reference-rays 16 --quiet";

// A PNG header claiming w x h pixels (8-bit grayscale) over one empty IDAT: a decompression bomb
// as far as a decoder that trusts the header is concerned.
std::string pngHeader(uint32_t w, uint32_t h) {
    std::string p = "\x89PNG\r\n\x1a\n";
    auto be32 = [&](uint32_t v) {
        for (int k = 3; k >= 0; --k)
            p.push_back(char((v >> (8 * k)) & 255));
    };
    be32(13), p += "IHDR", be32(w), be32(h), p += std::string("\x08\x00\x00\x00\x00", 5), be32(0);
    be32(2), p += "IDAT", p += "\x78\x01", be32(0);
    be32(0), p += "IEND", be32(0);
    return p;
}
} // namespace

TEST(CliBudgets, AScoreImageIsReadThroughTheFileGate) {
    // Before: stb opened the path itself; a FIFO blocked the render for ever after the reference.
    const std::string fifo = std::string(SSAOLAB_TEST_TMP) + "/score_fifo.png";
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const CliRun r = ssaolab(kView + " --out " + outDir("budget_fifo") + " --score " + fifo, "timeout 20"); // 124: hung
    expectCleanFailure(r, "is a FIFO, not a regular file");
    std::filesystem::remove(fifo);
}

TEST(CliBudgets, AScoreImageBombIsRefusedFromItsHeader) {
    // Before: a 30000 x 30000 header made stb reserve 3.4 GiB before it found no data.
    const std::string bomb = writeTemp("score_bomb.png", pngHeader(30000, 30000));
    const CliRun r = ssaolab(kView + " --out " + outDir("budget_bomb") + " --score " + bomb);
    expectCleanFailure(r, "is 30000x30000 pixels: past the budget of 64 M pixels");
    EXPECT_NE(r.err.find("--max-mask-mpix"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(bomb), std::string::npos) << r.err;
}

TEST(CliBudgets, AScoreImageWithAoOutsideZeroToOneIsRefused) {
    // Before: an EXR of AO 1.5 and -0.25 was scored as if it were AO.
    ssao::Image img{64, 36, 1, std::vector<float>(64 * 36, 0.5f)};
    img.data[0] = 1.5f, img.data[7] = -0.25f, img.data[100] = 1.0001f;
    const std::string path = std::string(SSAOLAB_TEST_TMP) + "/score_range.exr";
    ssao::writeExr(img, path);
    const CliRun r = ssaolab(kView + " --out " + outDir("budget_range") + " --score " + path);
    expectCleanFailure(r, "--score " + path + ": 3 pixels hold AO outside [0, 1]");
}

TEST(CliBudgets, TheOracleGBufferIsBudgetedBeforeTheRender) {
    // Before: a 4096-pixel guard band and two layers took 3.5 GiB, after the whole reference trace.
    const CliRun r = ssaolab(kView + " --out " + outDir("budget_oracle") + " --oracle-layers 2 --oracle-guard 4096");
    expectCleanFailure(r, "screen oracle: its G-buffer would take 3.54 GiB");
    EXPECT_NE(r.err.find("past the budget of 1 GiB"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--oracle-guard"), std::string::npos) << r.err;
    EXPECT_EQ(ssaolab(kView + " --out " + outDir("budget_oracle_ok") + " --oracle-layers 2 --oracle-guard 16").exitCode, 0);
}
