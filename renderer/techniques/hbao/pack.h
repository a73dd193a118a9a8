// HBAO settings → its GPU constants (shaders/techniques/hbao/layout.h), pure and tested.
#pragma once
#include "techniques/technique_settings.h"

#include "../../../shaders/include/bindings.h"
#include "../../../shaders/techniques/hbao/layout.h"

namespace ssao {

gpu::HbaoConstants packHbaoConstants(const HbaoSettings& s, const gpu::AoCommon& common);

} // namespace ssao
