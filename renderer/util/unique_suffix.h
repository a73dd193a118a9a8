// Short display names for distinct file paths: two files named scene.gltf in different folders
// stay two names ("a/scene.gltf", "b/scene.gltf"); a file alone with its stem is named by it.
#pragma once
#include <string>
#include <vector>

namespace ssao {

// For each of the distinct `paths`, the first of its stem, its file name, then its last 2, 3, ...
// components ("a/scene.gltf") that is not a candidate of any other path nor one of `taken` (names
// already in use, e.g. builtin:showcase); the whole path when none is.
std::vector<std::string> shortestUniqueSuffixes(const std::vector<std::string>& paths,
                                                const std::vector<std::string>& taken = {});

} // namespace ssao
