// JSON from files, read defensively: only regular files (a FIFO would block the read for ever),
// at most a stated size, nesting bounded before anything is parsed (nlohmann's copies and
// destruction, and tinygltf's conversion, recurse once per level: 20 000 nested arrays in a 40 KB
// file exhausted the stack), and errors as one ssao::Error naming the file.
#pragma once
#include "util/files.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace ssao {

constexpr size_t kMaxJsonDepth = 64;          // glTF nests ~8 deep, presets and sweeps ~4
constexpr size_t kMaxJsonBytes = kMaxFileBytes; // 64 MiB of text

// The deepest nesting of arrays and objects in JSON text (strings skipped); no recursion.
size_t jsonNestingDepth(const char* text, size_t size);
// Throws "WHAT nests deeper than 64 levels" when it does.
void checkJsonNesting(const std::string& text, const std::string& what);
// checkJsonNesting + parse; a syntax error is "LABEL is not valid JSON (REASON)", never quoting the text.
nlohmann::json parseJsonText(const std::string& text, const std::string& label);
// readRegularFile + parseJsonText; a syntax error names the file, a binary file (an image, a GLB)
// is named as what it is: "WHAT PATH is a PNG image, not a WHAT (JSON text)".
nlohmann::json readJsonFile(const std::string& path, const std::string& what);
// Text for JSON output whatever bytes a string holds (a file name that is not UTF-8): invalid
// sequences become U+FFFD, so a dump never throws half way through a report.
std::string dumpJson(const nlohmann::json& j, int indent = 2);

} // namespace ssao
