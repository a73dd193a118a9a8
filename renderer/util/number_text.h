// A number as text, in the format it lands in: printf's conversion (`fmt`: "%.4f", "%.*g" with
// `digits`), and a missing (non-finite) value as that format's own mark - an empty cell in CSV, a
// dash in Markdown and HTML pages, "nan"/"inf" spelled out where a message must show it.
#pragma once
#include <string>

namespace ssao {

enum class Missing {
    EmptyCell, // CSV: "" (a reader's missing value)
    Dash,      // Markdown and HTML: "–"
    Spelled,   // messages: printf's own "nan", "inf"
};

std::string numberText(double v, const char* fmt, Missing missing = Missing::Dash);
// `fmt` takes the digits first ("%.*g", "%.*f").
std::string numberText(double v, const char* fmt, int digits, Missing missing = Missing::Dash);

} // namespace ssao
