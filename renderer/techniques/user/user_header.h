// A user technique is one GLSL file, NAME.ao.glsl: its parameters are declared in a
// header that uses ReShade FX's uniform annotation syntax inside one GLSL block comment, so the
// file stays valid GLSL and post-process authors already know how to write it:
//
//   /*ssaolab
//   interface = 1;                 // required: the input interface the body is written against (only 1)
//   label = "Crytek-style kernel";  // optional, <= 48 chars; default: NAME
//   summary = "one line";           // optional, <= 160 chars
//   uniform float radius_scale < ui_type = "slider"; ui_min = 0.25; ui_max = 4.0; ui_step = 0.05;
//       ui_label = "Radius scale"; ui_units = " x R"; ui_tooltip = "Scales the world radius R."; > = 1.0;
//   uniform int samples < ui_type = "slider"; ui_min = 1; ui_max = 64; > = 16;
//   uniform bool use_normals < ui_label = "Use normals"; > = true;
//   uniform int falloff < ui_type = "combo"; ui_items = "none\0linear\0smooth\0"; > = 1;
//   */
//
// - The header is the first block comment whose text starts with "ssaolab" (then a blank or the
//   comment's end) right after the opening slash-star; it ends at the first star-slash, as GLSL
//   ends it (so no string in it may hold one). Everything else is the shader body, only
//   size-checked here. No header, or a second one, is an error.
// - Statements end with ';'; blanks and newlines are free; '//' comments run to the line's end
//   (not inside a string).
// - A parameter: `uniform TYPE NAME [< ANNOTATION = VALUE; ... >] = DEFAULT;`, TYPE float, int or
//   bool (no arrays, no vectors). A float or int needs ui_min and ui_max: the UI's slider, tuning
//   and stress runs use the range. An int with ui_type "combo", "radio" or "list" and ui_items is
//   an enum: its value is the item's index (0 .. items-1), its range comes from the items.
// - Annotations: ui_type (slider, drag or input; combo, radio or list for an enum; checkbox or
//   none for a bool), ui_min, ui_max, ui_step, ui_label (<= 48), ui_tooltip (<= 200), ui_units
//   (<= 16), ui_items. ReShade's ui_category, ui_category_closed, ui_spacing, ui_text, hidden and
//   source are accepted and ignored (their strings are not checked); any other name is an error.
// - Numbers: decimal, a leading '-', floats with an optional exponent and 'f' suffix; an int's
//   numbers are whole (no point, exponent or suffix); bools take true or false.
// - Strings: double quotes, escapes \" \\ and \0 (the item separator, only in ui_items; a trailing
//   one is optional), printable ASCII only: they reach the UI, JSON presets and HTML reports.
// - Limits: at most 24 parameters; a name matches [a-z_][a-z0-9_]{0,31}, is unique, does not
//   start with gl_ or ssao_, holds no "__" and is no GLSL keyword, type or built-in function;
//   ui_min < ui_max, both finite, the default within them, ui_step > 0; a float's numbers within
//   +-1e9, an int's within +-1e6; an enum has 1 to 16 distinct items of 1 to 32 characters and no
//   ui_min, ui_max or ui_step; a bool takes none of those nor ui_items; the file <= 256 KiB, the
//   header <= 16 KiB.
// - An enum item becomes a #define of NAME_ITEM in capitals (letters and digits kept, every other
//   run as one '_'), so items must differ as such names, hold a letter or digit, and the names
//   may not begin with GL_.
// Every error is one ssao::Error "FILE:LINE: message", LINE the line of the offending token (a
// missing ';', '=' or default: the line of the token it should follow; the file's size and a
// missing header: line 1; the header's size and a missing `interface`: the header's first line).
#pragma once
#include <string>
#include <vector>

namespace ssao {

constexpr size_t kMaxUserFileBytes = size_t(256) << 10;  // the whole NAME.ao.glsl
constexpr size_t kMaxUserHeaderBytes = size_t(16) << 10; // from its opening to its closing comment mark
constexpr int kMaxUserParams = 24;
constexpr int kUserInterfaceVersion = 1; // the one input interface a body can be written against

struct UserParam {
    std::string name, label, tooltip, unit; // label: ui_label, or the name when not given
    enum class Type { Float, Int, Bool, Enum } type = Type::Float;
    // Enum: 0 .. items-1, a bool 0 .. 1; step: ui_step, 0 when not given; def: the default
    // (a bool's 0 or 1, an enum's index).
    double min = 0, max = 1, step = 0, def = 0;
    std::vector<std::string> items; // Enum only, in order
    int line = 0;                   // of its `uniform`
};

struct UserHeader {
    int interface = kUserInterfaceVersion;
    std::string label, summary;
    std::vector<UserParam> params;
};

// The header of a NAME.ao.glsl file's text (at most 256 KiB, read through util/files.h by the
// caller). `file` is its path as the caller names it in errors; NAME comes from it
// (userTechniqueName) and is the label when the header gives none.
UserHeader parseUserHeader(const std::string& text, const std::string& file, const std::vector<std::string>& builtinIds);

// NAME of a path ending in NAME.ao.glsl: [a-z][a-z0-9_]{0,23}, not one of the built-in technique
// ids. Throws one line "PATH: message" (a file's name has no line).
std::string userTechniqueName(const std::string& path, const std::vector<std::string>& builtinIds);

// The GLSL the body is compiled with, after #version and ahead of the file's text: a std140
// uniform block SsaoUserParams at `binding`, one member per parameter in order, named as the
// parameter (a float as float; an int, enum or bool as int: std140 bools are 4 bytes but not
// every driver packs them alike, so a bool is 0 or 1 in an int); a header with no parameters gets
// one placeholder int, ssao_no_params, as GLSL has no empty blocks. Then one #define per enum item
// (`#define FALLOFF_NONE 0`), and last `#line 1`: the next line is line 1, so when the file's text
// follows at once the compiler's line numbers are the file's.
std::string userParamsGlsl(const UserHeader& h, int binding);

// The block's bytes for `values` (one per parameter, in order): every member a 4-byte scalar at
// offset 4*i (float as float32, int and enum as int32, bool as int32 0 or 1), the size rounded up
// to 16, at least 16. A wrong count, or a value that is not finite, outside its parameter's range
// or (int, enum) not whole, is an error.
std::vector<unsigned char> packUserParams(const UserHeader& h, const std::vector<double>& values);

// FNV-1a 64 of the file's text as 16 lowercase hex digits: a preset names the file it was tuned on.
std::string userTechniqueHash(const std::string& text);

} // namespace ssao
