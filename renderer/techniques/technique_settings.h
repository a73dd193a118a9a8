// One member per AO technique. Settings (settings/settings.h) inherits this struct, so a pass
// reads `settings.kernel.samples`. Adding a technique adds one member (and its include) here.
#pragma once
#include "techniques/gtao/settings.h"
#include "techniques/hbao/settings.h"
#include "techniques/kernel/settings.h"
#include "techniques/sao/settings.h"
#include "techniques/vbao/settings.h"

namespace ssao {

// The technique a new Settings{} uses.
constexpr const char* kDefaultTechnique = "kernel";

struct TechniqueSettings {
    KernelSettings kernel;
    GtaoSettings gtao;
    HbaoSettings hbao;
    SaoSettings sao;
    VbaoSettings vbao;
};

} // namespace ssao
