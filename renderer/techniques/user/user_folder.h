// The user's techniques folder: every NAME.ao.glsl directly in it (user_source.h), read through the
// file gate (util/files.h) - regular files only, no links followed, at most 256 KiB each; the first
// 256 technique files by name are read, the rest named as not loaded (the built-ins always are). Where it is: --technique-dir, else SSAOLAB_TECHNIQUE_DIR, else
// $XDG_CONFIG_HOME/ssaolab/techniques, else ~/.config/ssaolab/techniques (beside the presets).
#pragma once
#include "techniques/user/user_source.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ssao {

constexpr size_t kMaxUserFolderFiles = 256;
constexpr size_t kMaxUserFolderEntries = 65536; // entries of any kind looked at in the folder

struct TechniqueFolderList {
    std::vector<std::string> files; // the NAME.ao.glsl names (regular files), sorted, at most kMaxUserFolderFiles
    std::vector<std::string> over;  // technique files past the cap, sorted
    bool truncated = false;         // the folder held more than kMaxUserFolderEntries entries: the rest unread
};
// The technique files directly in `dir` (never a subfolder, never a link). An unreadable folder throws.
TechniqueFolderList listTechniqueFiles(const std::string& dir);

std::string defaultUserTechniqueDir(); // "" when there is no home to put it under

struct UserTechniqueScan {
    std::vector<std::shared_ptr<const UserTechnique>> loaded; // by name
    // "user.NAME" -> "FILE:LINE: why" for each file whose header, body or name was refused.
    std::vector<std::pair<std::string, std::string>> refused;
    // "user.NAME" -> why, for files past the folder's cap: not read, named in one warning.
    std::vector<std::pair<std::string, std::string>> over;
    std::string overWarning; // that one warning ("" when none)
};

// The folder's techniques. A folder that is absent holds none when `mustExist` is false (the
// default folder) and is an error otherwise (one the user named).
UserTechniqueScan scanUserTechniques(const std::string& dir, bool mustExist);

// One technique's file by its path (the explorer re-reads a changed one), refused as the scan does.
std::shared_ptr<const UserTechnique> readUserTechnique(const std::string& path);

} // namespace ssao
