#include "cli/user_techniques.h"

#include "cli/cli_util.h"
#include "techniques/technique.h"
#include "techniques/user/user_folder.h"

namespace ssao {

std::string loadUserTechniques(const std::string& techniqueDir) {
    const std::string dir = techniqueDir.empty() ? defaultUserTechniqueDir() : techniqueDir;
    const UserTechniqueScan scan = scanUserTechniques(dir, !techniqueDir.empty());
    std::vector<std::string> warnings;
    for (const auto& [id, why] : scan.refused)
        warnings.push_back(why + " (" + id + " is not available)");
    if (!scan.overWarning.empty()) warnings.push_back(scan.overWarning); // one line for every file past the cap
    printWarnings(warnings);
    std::vector<std::pair<std::string, std::string>> refused = scan.refused;
    refused.insert(refused.end(), scan.over.begin(), scan.over.end());
    if (!scan.loaded.empty() || !refused.empty()) setUserTechniques(scan.loaded, refused);
    return dir;
}

} // namespace ssao
