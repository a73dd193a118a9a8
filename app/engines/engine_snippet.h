// The tuned settings as code for the engine's own API, ready to paste after the pass is made: one
// statement per parameter as its table writes it - a property assignment
// (`n8aopass.configuration.aoRadius = 1.25;`) or one update call per setter with an object of its
// keys (`gtaoPass.updateGtaoMaterial({ radius: 0.31, thickness: 1.2 });`); a constructor argument
// as a comment on the construction. Comment lines first: where the numbers come from, in ssaolab's
// own words; then the names they come from (scene, view, file) as string literals in one statement
// that does nothing, never in a comment - the one writer of code users paste.
#pragma once
#include "engines/engine_table.h"

#include <string>
#include <utility>
#include <vector>

namespace ssao {

// A number as the snippet and the settings JSON both write it: 6 significant digits, so the JSON's
// value and the snippet's text are the same number.
double exportedValue(double v);
// `v` as JavaScript source for the row's type (true/false, an integer, a number).
std::string jsValue(const EngineParam& p, double v);

struct SnippetFacts {
    // ssaolab's own words and numbers, a comment line each (printable ASCII only: output/escape.h
    // jsCommentText); no name from input goes here.
    std::vector<std::string> notes;
    // Names from input (a scene's file, a view), as `void { key: "value", ... };` with each value
    // a string literal (output/escape.h jsString); keys are ssaolab's identifiers.
    std::vector<std::pair<std::string, std::string>> names;
};

// `values`: row names and values, in the order given; unknown names throw. The result parses as a
// script and as a module.
std::string engineSnippet(const EngineTable& t, const std::vector<std::pair<std::string, double>>& values,
                          const SnippetFacts& facts);

} // namespace ssao
