// A user technique (NAME.ao.glsl, user_source.h) as a technique like the built-ins: id "user.NAME",
// one row "user.NAME.PARAM" per header parameter (label, tooltip, unit, range and default from its
// annotations), plus "user.NAME.ssao_noise", the frame's noise kind ssaoNoise() returns (a header
// name may not start with ssao_, so it cannot collide). Values live in Settings::user (settings.h).
#pragma once
#include "techniques/noise/noise.h"
#include "techniques/technique.h"
#include "techniques/user/user_source.h"

#include <memory>
#include <string>
#include <vector>

namespace ssao {

std::string userTechniqueId(const std::string& name); // "user." + name
constexpr const char* kUserNoiseRow = "ssao_noise";

TechniqueInfo userTechniqueInfo(std::shared_ptr<const UserTechnique> t);

// The technique's parameter values in `s`, one per header parameter in order (absent: the default).
std::vector<double> userParamValues(const UserTechnique& t, const Settings& s);
AoNoise userNoise(const UserTechnique& t, const Settings& s);

} // namespace ssao
