// The parameter table's core rows (gbuffer, ao, denoise, temporal, composite, skip): params.cpp
// joins them with each registered technique's rows.
#pragma once
#include "base/param.h"

#include <vector>

namespace ssao {

std::vector<Param> coreParamRows();

} // namespace ssao
