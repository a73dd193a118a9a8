// Visibility-bitmask AO: the module's entry for the technique registry.
#pragma once
#include "techniques/technique.h"

namespace ssao {
TechniqueInfo vbaoTechnique();
} // namespace ssao
