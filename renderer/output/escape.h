// One escaper per output sink: every string a report writes that came from input (scene, preset,
// label, sweep, group, viewpoint, hostname, GL renderer, ...) goes through the one for its file.
// Numbers a writer formats itself (-0.003 bias) are written raw: they are not input, and a CSV
// number must stay a number.
#pragma once
#include <string>

namespace ssao {

// HTML element content (text nodes, <title>, SVG <text>/<title>): & < > " ' as entities.
std::string htmlText(const std::string& s);
// A double-quoted attribute value (the writers never emit unquoted attributes): the same set.
std::string htmlAttr(const std::string& s);
// A Markdown table cell or a run of inline text: | \ ` * _ [ ] backslash-escaped, & < > as
// entities (no raw HTML, no autolink), CR and LF as spaces (one row stays one line).
std::string markdownCell(const std::string& s);
// One RFC 4180 field of text: a leading = + - @ TAB or CR gets a ' in front (OWASP: no formula
// when a spreadsheet opens it), then the field is quoted, "" for ", when it holds , " CR or LF.
std::string csvField(const std::string& s);
// A double-quoted JavaScript string literal that is pure printable ASCII: every other character as
// \uXXXX (U+2028 and U+2029 end a line in JavaScript, even inside a // comment; invalid UTF-8 as
// U+FFFD), and " \ < > escaped, so it parses the same as a script, a module, JSON or inside a
// <script> element.
std::string jsString(const std::string& s);
// The text of one // comment line: printable ASCII only, every other byte as '?' (nothing a comment
// holds can end it). Names never go here: they go through jsString.
std::string jsCommentText(const std::string& s);

} // namespace ssao
