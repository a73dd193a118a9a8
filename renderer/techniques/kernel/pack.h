// Kernel SSAO settings → its GPU constants (shaders/techniques/kernel/layout.h): the one pure
// function between what a person sets and what the shader reads (XeGTAO's GTAOUpdateConstants).
#pragma once
#include "techniques/technique_settings.h"

#include "../../../shaders/include/bindings.h"
#include "../../../shaders/techniques/kernel/layout.h"

namespace ssao {

// `common` comes from packAoCommon (radius, power, target size, the normal encoding).
gpu::KernelConstants packKernelConstants(const KernelSettings& s, const gpu::AoCommon& common);

} // namespace ssao
