// Display names of scene files: distinct paths keep distinct names, as short as that allows.
#include "util/unique_suffix.h"

#include <gtest/gtest.h>

using namespace ssao;
using V = std::vector<std::string>;

TEST(UniqueSuffix, AStemAloneWhenNoOtherFileHasIt) {
    EXPECT_EQ(shortestUniqueSuffixes({"/s/CornellBox/cornellBox.gltf", "/s/Lantern/Lantern.gltf"}),
              (V{"cornellBox", "Lantern"}));
    EXPECT_EQ(shortestUniqueSuffixes({"/x/one.gltf"}), (V{"one"}));
    EXPECT_EQ(shortestUniqueSuffixes({}), V{});
}

TEST(UniqueSuffix, SameFileNameInTwoFoldersGetsItsFolder) {
    EXPECT_EQ(shortestUniqueSuffixes({"/t/a/scene.gltf", "/t/b/scene.gltf", "/t/c/other.gltf"}),
              (V{"a/scene.gltf", "b/scene.gltf", "other"}));
    // The same folder name higher up: as many components as it takes.
    EXPECT_EQ(shortestUniqueSuffixes({"/p/x/a/scene.gltf", "/q/x/a/scene.gltf"}),
              (V{"p/x/a/scene.gltf", "q/x/a/scene.gltf"}));
}

TEST(UniqueSuffix, SameStemOtherExtensionKeepsTheExtension) {
    EXPECT_EQ(shortestUniqueSuffixes({"/t/scene.gltf", "/t/scene.glb"}), (V{"scene.gltf", "scene.glb"}));
}

TEST(UniqueSuffix, NamesInUseAreNotTaken) {
    EXPECT_EQ(shortestUniqueSuffixes({"/t/showcase.gltf"}, {"showcase"}), (V{"showcase.gltf"}));
    // A stem that is another file's name: neither is ambiguous once both are long enough.
    const V n = shortestUniqueSuffixes({"/t/a.gltf.gltf", "/u/a.gltf"});
    EXPECT_NE(n[0], n[1]);
}

TEST(UniqueSuffix, DistinctPathsAlwaysGetDistinctNames) {
    const V paths = {"/a/b/c.gltf", "/b/c.gltf", "/c.gltf", "/a/c.glb", "/x/c.gltf/c.gltf", "/c/b/c.gltf"};
    const V n = shortestUniqueSuffixes(paths);
    ASSERT_EQ(n.size(), paths.size());
    for (size_t i = 0; i < n.size(); ++i)
        for (size_t j = i + 1; j < n.size(); ++j)
            EXPECT_NE(n[i], n[j]) << paths[i] << " and " << paths[j];
}
