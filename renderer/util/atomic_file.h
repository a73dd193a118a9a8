// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file beside it, every write, the flush and the close are checked (a full disk shows up at any of
// them), and only then is it renamed over the destination. Without this a full disk left a 0-byte
// metrics.json and empty PNGs while the CLI printed "wrote ...".
#pragma once
#include <string>

namespace ssao {

// Throws ssao::Error("cannot write PATH: REASON") naming the file and the system's reason.
void writeFileAtomically(const std::string& path, const std::string& bytes);

} // namespace ssao
