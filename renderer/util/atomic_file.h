// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file beside it, every write, the flush and the close are checked (a full disk shows up at any of
// them), and only then is it renamed over the destination. Without this a full disk left a 0-byte
// metrics.json and empty PNGs while the CLI printed "wrote ...".
#pragma once
#include <string>

namespace ssao {

// Throws ssao::Error("cannot write PATH: REASON") naming the file and the system's reason. The
// destination must be absent or a regular file (a device, a FIFO, a folder or a symlink is refused:
// `--out /dev/null` must not replace the device node); the temporary file is created exclusively
// (O_EXCL, O_NOFOLLOW) under a name unique to the process and the call, so a link planted at it
// cannot redirect the write and two processes writing one folder never share it.
void writeFileAtomically(const std::string& path, const std::string& bytes);
// The destination check alone: absent in a folder that exists, or a regular file.
void checkOutputPath(const std::string& path);

} // namespace ssao
