#include "commands/probe/probe_command.h"

#include "cli/headless_runner.h"
#include "settings/params.h"
#include "techniques/technique.h"
#include "techniques/user/user_folder.h"
#include "techniques/user/user_technique.h"

#include <cstdio>

namespace ssao {

int runProbeTechnique(const std::string& file, int width, int height) {
    const std::shared_ptr<const UserTechnique> t = readUserTechnique(file);
    setUserTechniques({t});
    Settings s = defaultSettings();
    s.ao.technique = userTechniqueId(t->name);
    HeadlessRunner run;
    const Scene scene = loadNamedScene("builtin:showcase");
    auto r = run.makeRenderer(width, height);
    r->setScene(scene);
    r->setCamera(defaultCamera(scene));
    r->setSettings(s);
    r->render();
    run.readFinite(*r, "ao.raw", t->path);
    r->inspect(0, {width / 2, height / 2}); // the inspector's variant compiles and runs too
    run.checkGl(t->path);
    std::printf("ok %s\n", t->hash.c_str());
    return 0;
}

} // namespace ssao
