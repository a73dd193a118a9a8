// A web engine's AO settings as data (tools/peers/engines/NAME.json, beside the runner that
// applies them): the engine's own parameter names, types, ranges, defaults and units for the
// package version the lock pins, and each one's role - shape (what the AO estimates: fitted to the
// reference by `tune --engine`), cost (sample counts and denoisers: chosen by a budget, never
// fitted) or fixed (set by the harness to read the AO alone, or a mode that changes another
// setting's unit). peers.js writes and reads every parameter where its row says; the snippet
// `tune --engine` writes sets it the same way.
#pragma once
#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ssao {

struct EngineParam {
    enum class Role { Shape, Cost, Fixed };
    enum class Type { Number, Integer, Boolean };
    std::string name; // unique in the table; the engine's own key is writeKey for update calls
    Type type = Type::Number;
    Role role = Role::Fixed;
    double defaultValue = 0; // booleans: 0 or 1
    std::optional<std::pair<double, double>> range; // none: not documented (fixed rows only)
    std::string unit;
    // How the engine takes it: a property path ("configuration.aoRadius"), an update call with a
    // key (updateGtaoMaterial({radius})), or a constructor argument (its index).
    std::string writePath, writeCall, writeKey;
    int constructorArg = -1;
    // Shape rows: the search space, in units of the harness's value for the view (relative) or of
    // the parameter itself; log: grid spaced evenly in log(value).
    // perRadius: in units of R^perRadius of the view (1: a length the engine compares with scene
    // distances, such as SAOPass's bias under the harness's scale; -1: a factor on such a length,
    // such as its intensity), so one value fits scenes of any scale; 0: not.
    bool relative = false, log = false;
    int perRadius = 0;
    double searchLo = 0, searchHi = 0;
    // Cost rows: the value scales with a time budget (a sample count: more is a finer estimate of the
    // same AO); `tune --engine --budget-*` multiplies every such row by one factor.
    bool scalesWithBudget = false;
    nlohmann::json row; // the row as the table writes it (sent to the runner)
};

struct EngineTable {
    std::string engine, title, package, version, peer, file;
    std::string page = "peers.html"; // the harness page that runs it (babylon.html, playcanvas.html)
    std::string variable;           // the snippet's name for the pass ("n8aopass")
    std::vector<std::string> setup; // the snippet's opening lines (import, construction)
    // Arguments a setter's call always carries, beside the tuned values (Filament's
    // setAmbientOcclusionOptions falls back to enabled: false): setter -> (key, JavaScript literal).
    std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> callAlways;
    std::vector<EngineParam> params;

    const EngineParam* find(const std::string& name) const;
};

// The runner's folder, tools/peers under the data root (the source tree or an installation's share/ssaolab).
std::string enginePeersDir();
// The engines there, sorted ("n8ao", "three-gtao", ...).
std::vector<std::string> engineNames();
// Parses and checks one table: every row's fields, types and roles; every default inside its
// range; every shape row with a search range. Throws ssao::Error naming the file and the row.
EngineTable loadEngineTable(const std::string& path);
// The table of an engine by name; an unknown name throws listing the engines.
EngineTable findEngine(const std::string& name);
// A value as the engine's type writes it in JSON (true/false, an integer, a number).
nlohmann::json engineValueJson(const EngineParam& p, double v);
// A value a file gives for `p`, checked against its row: its type (true/false; a finite number; an
// integer), inside the row's range. Throws one line "WHERE must be ..." naming the range. Every
// engine value read from a file goes through it, and tune's own output before it is written.
double checkedEngineValue(const EngineParam& p, const nlohmann::json& v, const std::string& where);
// The engine as its package ships it: each row the harness sets from R (a shape or cost row with a
// "harness" value) at the table's default; the fixed rows that read the AO alone stay the harness's.
std::map<std::string, double> shippedValues(const EngineTable& t);
// The row's range as text: "[lo, hi]" ("any" when it documents none).
std::string engineRangeText(const EngineParam& p);

} // namespace ssao
