// Settings, whole: the shared blocks (base/shared_settings.h) and one member per AO technique, so a
// pass reads `settings.kernel.samples`. Adding a technique adds one member (and its include) here.
// It lives with the techniques because it names each of them; settings/ (the parameter table and
// presets) sits above and reads it.
#pragma once
#include "base/shared_settings.h"
#include "techniques/gtao/settings.h"
#include "techniques/hbao/settings.h"
#include "techniques/kernel/settings.h"
#include "techniques/sao/settings.h"
#include "techniques/user/settings.h"
#include "techniques/vbao/settings.h"

namespace ssao {

struct TechniqueSettings {
    KernelSettings kernel;
    GtaoSettings gtao;
    HbaoSettings hbao;
    SaoSettings sao;
    VbaoSettings vbao;
    UserSettings user; // every user technique's values (techniques/user/user_technique.h)
};

struct Settings : TechniqueSettings {
    GBufferSettings gbuffer;
    AoSettings ao;
    DenoiseSettings denoise;
    TemporalSettings temporal;
    CompositeSettings composite;
    SkipSettings skip;
};

} // namespace ssao
