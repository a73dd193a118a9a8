// examples/techniques/learnopengl.ao.glsl carries the built-in kernel's points and noise tile as
// constants (a user file cannot upload them): each literal must read back as the generator's float
// exactly (techniques/kernel/sampling.cpp), or the example's AO would drift from its twin's at
// sample counts the GL test does not render.
#include "techniques/kernel/sampling.h"
#include "util/files.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace ssao;

namespace {

// The numbers inside `const TYPE NAME[...] = TYPE[](...);` in order.
std::vector<float> table(const std::string& text, const std::string& name) {
    const size_t at = text.find(name + "[");
    EXPECT_NE(at, std::string::npos) << name;
    const size_t open = text.find("](", at), close = text.find(");", at);
    std::vector<float> out;
    const char* p = text.c_str() + open + 2;
    const char* end = text.c_str() + close;
    while (p < end) {
        if (std::strchr("-0123456789.", *p) && !(p[-1] >= 'a' && p[-1] <= 'z') && !(p[-1] >= '0' && p[-1] <= '9')) {
            char* next = nullptr;
            out.push_back(std::strtof(p, &next));
            p = next;
        } else {
            ++p;
        }
    }
    return out;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

} // namespace

TEST(UserExamples, TheLearnOpenGlExamplesConstantsAreTheGeneratorsFloats) {
    const std::string text = readRegularFile(std::string(SSAOLAB_SOURCE_DIR) + "/examples/techniques/learnopengl.ao.glsl",
                                             "example");
    const std::vector<float> kernel = table(text, "KERNEL"), tile = table(text, "TILE");
    ASSERT_EQ(kernel.size(), 3u * 256u);
    ASSERT_EQ(tile.size(), 2u * 16u);
    // Kernel point i before its scale: makeKernel's draws for seed 0 (five a point, none rejected).
    Rng rng(0);
    for (int i = 0; i < 256; ++i) {
        const float x = rng.uniform(-1.0f, 1.0f), y = rng.uniform(-1.0f, 1.0f), z = rng.uniform(0.0f, 1.0f);
        rng.uniform(-1.0f, 1.0f); // the sphere's z
        const glm::vec3 w = glm::normalize(glm::vec3(x, y, z)) * rng.uniform();
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(sameBits(kernel[size_t(3 * i + c)], w[c])) << "KERNEL[" << i << "]." << c;
    }
    // And scaled, they are makeKernel's points at the learnopengl preset's 64 and at the row's 256.
    for (const int n : {64, 256}) {
        const std::vector<glm::vec3> k = makeKernel(SampleSet::Hemisphere, n, 0);
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_TRUE(sameBits(kernel[size_t(3 * i + c)] * kernelScale(i, n), k[size_t(i)][c])) << n << " " << i;
    }
    const std::vector<glm::vec3> noise = makeNoise(0);
    for (int j = 0; j < 16; ++j) {
        EXPECT_TRUE(sameBits(tile[size_t(2 * j)], noise[size_t(j)].x)) << "TILE[" << j << "].x";
        EXPECT_TRUE(sameBits(tile[size_t(2 * j + 1)], noise[size_t(j)].y)) << "TILE[" << j << "].y";
    }
}
