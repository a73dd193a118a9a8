// What `bench`, `tune` and `skips` share: measuring (measure/measurement.h), the bench's radius, and
// the run's facts.
#pragma once
#include "measure/measurement.h"
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ssao {

// The settings a configuration runs with: its own, with the bench's world radius R.
Settings withRadius(Settings s, float radius);

// Machine, GL renderer, build type, date, git revision.
nlohmann::json runFacts(const std::string& glRenderer);

} // namespace ssao
