// The user techniques of a run (renderer/techniques/user/user_folder.h), registered before
// anything reads the parameter table: the folder named by --technique-dir (which must exist), else
// the default one (which may not). A file that is refused is one `ssaolab: warning:` line naming
// FILE:LINE, and choosing its technique is the error.
#pragma once
#include <string>

namespace ssao {

// Returns the folder it read ("" when none). Throws ssao::Error for a named folder that is absent.
std::string loadUserTechniques(const std::string& techniqueDir);

} // namespace ssao
