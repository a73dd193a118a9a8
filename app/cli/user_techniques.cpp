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
    printWarnings(warnings);
    if (!scan.loaded.empty() || !scan.refused.empty()) setUserTechniques(scan.loaded, scan.refused);
    return dir;
}

} // namespace ssao
