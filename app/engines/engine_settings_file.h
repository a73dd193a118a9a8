// A `tune --engine --out` result read back as the fit it is, for `bench --engine-settings` and the
// explorer's Front tab alike: a knob fitted relative to the view's make-peers value is that factor
// (the runner multiplies, EngineJob::scale), one fitted per R is that multiple of R^exponent of the
// view it runs on, and every other setting (cost settings included) is the engine's own value - so
// a view of another scene gets what `tune` gave its held-out views.
#pragma once
#include "engines/engine_table.h"

#include <map>
#include <string>
#include <utility>

namespace ssao {

struct TunedEngine {
    EngineTable table;
    std::string file;
    std::map<std::string, double> scale;                       // x the view's make-peers value
    std::map<std::string, std::pair<double, int>> perRadius;   // factor x R^exponent
    std::map<std::string, double> values;                      // the engine's value
};

// Throws ssao::Error (one line naming the file, the field and the range it breaks): not a tune
// result, another package version than the installed table's, a parameter the engine lacks or
// fixes, a value of the wrong type or outside its row's range (table.h checkedEngineValue), a
// fitted factor outside the row's search range.
TunedEngine readTunedEngine(const std::string& file);
// The same checks on a result in memory: tune runs them on its own output before writing it.
TunedEngine parseTunedEngine(const nlohmann::json& j, const std::string& file);

// The values a job sets on a view of world radius R: `values` and `perRadius` resolved (integers
// rounded, 6 significant digits); `scale` goes to the runner as it is.
std::map<std::string, double> jobValues(const EngineTable& table,
                                        const std::map<std::string, std::pair<double, int>>& perRadius,
                                        const std::map<std::string, double>& values, double radius);
inline std::map<std::string, double> tunedJobValues(const TunedEngine& t, double radius) {
    return jobValues(t.table, t.perRadius, t.values, radius);
}

} // namespace ssao
