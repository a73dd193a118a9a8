// Where ssaolab's run-time files are. An installed binary (cmake --install) finds them next to
// itself — PREFIX/bin/ssaolab reads PREFIX/share/ssaolab/{shaders,assets,tools} — so the install can be
// moved anywhere; a binary in the build tree falls back to the source tree (development, where
// shader hot reload edits the real files). SSAOLAB_DATA_DIR overrides both.
#pragma once
#include <string>

namespace ssao {

std::string executablePath(); // this process's binary ("" if unknown)
std::string dataRoot();       // the folder holding shaders/ and assets/
inline std::string shaderRoot() {
    return dataRoot() + "/shaders";
}
inline std::string assetRoot() {
    return dataRoot() + "/assets";
}
// How dataRoot() was found: "SSAOLAB_DATA_DIR", "installed", "beside the binary" or "source tree".
std::string dataRootSource();

} // namespace ssao
