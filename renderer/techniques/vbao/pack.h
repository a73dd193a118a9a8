// Visibility-bitmask settings → its GPU constants (shaders/techniques/vbao/layout.h), pure and tested.
#pragma once
#include "techniques/technique_settings.h"

#include "../../../shaders/include/bindings.h"
#include "../../../shaders/techniques/vbao/layout.h"

namespace ssao {

gpu::VbaoConstants packVbaoConstants(const VbaoSettings& s, const gpu::AoCommon& common);

} // namespace ssao
