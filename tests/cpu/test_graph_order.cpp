// The frame graph orders passes from their declarations alone, and names the resource when the
// declarations cannot work (a missing producer, two producers, a cycle). Pure: no GL.
#include "graph/frame_graph.h"
#include "util/error.h"

#include <gtest/gtest.h>

using namespace ssao;

namespace {
PassDecl decl(std::vector<std::string> reads, std::vector<std::string> writes) {
    PassDecl d;
    d.reads = std::move(reads);
    for (auto& w : writes) {
        ResourceDesc r;
        r.name = w;
        d.writes.push_back(r);
    }
    return d;
}
std::vector<std::string> ordered(const std::vector<std::string>& names, const std::vector<PassDecl>& decls) {
    std::vector<std::string> out;
    for (size_t i : FrameGraph::order(names, decls))
        out.push_back(names[i]);
    return out;
}
std::string errorOf(const std::vector<std::string>& names, const std::vector<PassDecl>& decls) {
    try {
        FrameGraph::order(names, decls);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
using V = std::vector<std::string>;
} // namespace

TEST(GraphOrder, ProducersRunBeforeConsumersWhateverTheRegistrationOrder) {
    // Registered backwards: composite, denoise, ao, gbuffer.
    const V names = {"composite", "denoise", "ao", "gbuffer"};
    const std::vector<PassDecl> decls = {
        decl({"gbuffer.albedo", "ao.denoised"}, {"composite"}), decl({"ao.raw"}, {"ao.denoised"}),
        decl({"gbuffer.depth"}, {"ao.raw"}), decl({}, {"gbuffer.depth", "gbuffer.albedo"})};
    EXPECT_EQ(ordered(names, decls), (V{"gbuffer", "ao", "denoise", "composite"}));
}

TEST(GraphOrder, IndependentPassesKeepTheirRegistrationOrder) {
    const V names = {"gbuffer", "ao", "b.ao", "denoise", "b.denoise"};
    const std::vector<PassDecl> decls = {decl({}, {"g"}), decl({"g"}, {"a"}), decl({"g"}, {"b.a"}),
                                         decl({"a"}, {"d"}), decl({"b.a"}, {"b.d"})};
    EXPECT_EQ(ordered(names, decls), names);
}

TEST(GraphOrder, AMissingProducerNamesTheResourceAndTheReader) {
    const std::string e =
        errorOf({"gbuffer", "ao"}, {decl({}, {"gbuffer.depth"}), decl({"gbuffer.normals"}, {"ao.raw"})});
    EXPECT_NE(e.find("'ao' reads 'gbuffer.normals', which no pass writes"), std::string::npos) << e;
}

TEST(GraphOrder, TwoProducersOfOneResourceAreAnError) {
    const std::string e = errorOf({"a", "b"}, {decl({}, {"ao.raw"}), decl({}, {"ao.raw"})});
    EXPECT_NE(e.find("'ao.raw' is written by both 'a' and 'b'"), std::string::npos) << e;
}

TEST(GraphOrder, ACycleIsAnErrorNamingAResourceOnIt) {
    const std::string e = errorOf({"x", "y", "z"}, {decl({}, {"seed"}), decl({"seed", "z.out"}, {"y.out"}),
                                                    decl({"y.out"}, {"z.out"})});
    EXPECT_NE(e.find("cycle"), std::string::npos) << e;
    EXPECT_TRUE(e.find("'y.out'") != std::string::npos || e.find("'z.out'") != std::string::npos) << e;
    const std::string self = errorOf({"p"}, {decl({"p.out"}, {"p.out"})});
    EXPECT_NE(self.find("reads its own output 'p.out'"), std::string::npos) << self;
}

TEST(GraphOrder, ScaledSizesRoundUp) {
    EXPECT_EQ(scaledSize(641, 0.5f), 321); // half of an odd width keeps the last column
    EXPECT_EQ(scaledSize(640, 0.25f), 160);
    EXPECT_EQ(scaledSize(3, 0.25f), 1);
    EXPECT_EQ(scaledSize(1280, 1.0f), 1280);
}
