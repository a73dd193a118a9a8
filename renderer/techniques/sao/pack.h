// SAO settings → its GPU constants (shaders/techniques/sao/layout.h), pure and tested.
#pragma once
#include "techniques/technique_settings.h"

#include "../../../shaders/include/bindings.h"
#include "../../../shaders/techniques/sao/layout.h"

namespace ssao {

gpu::SaoConstants packSaoConstants(const SaoSettings& s, const gpu::AoCommon& common);

} // namespace ssao
