#include "techniques/user/user_folder.h"

#include "techniques/technique.h"
#include "techniques/user/user_technique.h"
#include "util/error.h"
#include "util/files.h"
#include "util/user_dirs.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace ssao {

namespace {
constexpr const char* kSuffix = ".ao.glsl";

bool isTechniqueFile(const std::string& relative) {
    const size_t n = std::char_traits<char>::length(kSuffix);
    return relative.find('/') == std::string::npos && relative.size() > n &&
           relative.compare(relative.size() - n, n, kSuffix) == 0;
}

// "user.NAME" for a file name that has no valid NAME: the name as it is, for the refusal's key.
std::string idOf(const std::string& file) {
    return userTechniqueId(file.substr(0, file.size() - std::char_traits<char>::length(kSuffix)));
}
} // namespace

std::string defaultUserTechniqueDir() {
    if (const std::string d = envValue("SSAOLAB_TECHNIQUE_DIR"); !d.empty()) return d;
    if (const std::string x = xdgUserDir("XDG_CONFIG_HOME", ".config"); !x.empty()) return x + "/techniques";
    return "";
}

std::shared_ptr<const UserTechnique> readUserTechnique(const std::string& path) {
    std::string text;
    try {
        text = readRegularFile(path, "user technique", kMaxUserFileBytes);
    } catch (const FileTooLarge&) {
        throw Error(path + ":1: the file is larger than " + std::to_string(kMaxUserFileBytes >> 10) + " KiB");
    }
    return std::make_shared<UserTechnique>(loadUserTechnique(text, path, builtinTechniqueIds()));
}

TechniqueFolderList listTechniqueFiles(const std::string& dir) {
    TechniqueFolderList list;
    std::error_code ec;
    size_t seen = 0;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        if (++seen > kMaxUserFolderEntries) {
            list.truncated = true;
            break;
        }
        const std::string name = it->path().filename().string();
        const auto st = it->symlink_status(ec);
        if (!ec && fs::is_regular_file(st) && isTechniqueFile(name)) list.files.push_back(name);
    }
    if (ec) throw Error("technique folder " + dir + ": cannot list it (" + ec.message() + ")");
    std::sort(list.files.begin(), list.files.end());
    if (list.files.size() > kMaxUserFolderFiles) {
        list.over.assign(list.files.begin() + long(kMaxUserFolderFiles), list.files.end());
        list.files.resize(kMaxUserFolderFiles);
    }
    return list;
}

UserTechniqueScan scanUserTechniques(const std::string& dir, bool mustExist) {
    UserTechniqueScan scan;
    std::error_code ec;
    const auto st = fs::symlink_status(dir, ec);
    if (dir.empty() || ec || !fs::exists(st)) {
        if (mustExist) throw Error("technique folder " + dir + " does not exist");
        return scan;
    }
    if (!fs::is_directory(st)) throw Error("technique folder " + dir + " is not a folder");
    const TechniqueFolderList list = listTechniqueFiles(dir);
    const std::string cap = std::to_string(kMaxUserFolderFiles);
    for (const std::string& f : list.over)
        scan.over.emplace_back(idOf(f), (fs::path(dir) / f).string() + ": not loaded: the technique folder holds more than " +
                                            cap + " technique files (the first " + cap + " by name are)");
    if (!list.over.empty() || list.truncated)
        scan.overWarning = "technique folder " + dir + ": " +
                           (list.truncated ? "more than " + std::to_string(kMaxUserFolderEntries) + " entries, the rest not read; "
                                           : std::string()) +
                           (list.over.empty() ? std::string("")
                                              : std::to_string(list.over.size()) + " technique files past the first " + cap +
                                                    " by name are not loaded (" + list.over.front() + " ... " + list.over.back() + ")");
    for (const std::string& f : list.files) {
        const std::string path = (fs::path(dir) / f).string();
        try {
            std::string text;
            try {
                text = readFileInside(dir, f, "user technique", kMaxUserFileBytes);
            } catch (const FileTooLarge&) {
                throw Error(path + ":1: the file is larger than " + std::to_string(kMaxUserFileBytes >> 10) + " KiB");
            }
            scan.loaded.push_back(std::make_shared<UserTechnique>(loadUserTechnique(text, path, builtinTechniqueIds())));
        } catch (const Error& e) {
            scan.refused.emplace_back(idOf(f), e.what());
        }
    }
    return scan;
}

} // namespace ssao
