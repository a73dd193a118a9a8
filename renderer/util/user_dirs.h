// The user's folders from the environment, per the XDG Base Directory specification: a variable
// that is empty counts as unset (an empty XDG_CACHE_HOME once put the cache at "/ssaolab", an empty
// XDG_CONFIG_HOME the presets at "/ssaolab/presets", both at the file system's root).
#pragma once
#include <cstdlib>
#include <string>

namespace ssao {

// $NAME, or "" when it is unset or empty.
inline std::string envValue(const char* name) {
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : std::string();
}

// $XDG_VAR/ssaolab, else $HOME/HOME_DEFAULT/ssaolab (HOME_DEFAULT ".cache" or ".config", the
// specification's defaults), else "" (no home: the caller picks a relative folder).
inline std::string xdgUserDir(const char* xdgVar, const char* homeDefault) {
    if (const std::string x = envValue(xdgVar); !x.empty()) return x + "/ssaolab";
    if (const std::string h = envValue("HOME"); !h.empty()) return h + "/" + homeDefault + "/ssaolab";
    return "";
}

} // namespace ssao
