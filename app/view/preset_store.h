// The app's preset list: the shipped seed presets (read-only, listed first) and the user's own,
// saved as preset JSON files in a folder (default $XDG_CONFIG_HOME/ssaolab/presets).
#pragma once
#include "settings/preset.h"

#include <string>
#include <vector>

namespace ssao {

struct PresetEntry {
    std::string name;
    std::string path;
    bool builtin = false;
};

class PresetStore {
  public:
    PresetStore(std::string builtinDir, std::string userDir);
    static std::string defaultUserDir();

    void refresh();
    const std::vector<PresetEntry>& entries() const { return entries_; }
    const PresetEntry* find(const std::string& name) const;
    Preset load(const std::string& name) const;
    // Saving, renaming and deleting work on user presets only; names are [A-Za-z0-9 _.-]+ and
    // may not shadow a built-in preset. Each throws ssao::Error with a one-line reason.
    std::string save(const Preset& p);
    void rename(const std::string& from, const std::string& to);
    void remove(const std::string& name);
    const std::string& userDir() const { return userDir_; }

  private:
    void checkName(const std::string& name) const;
    std::string builtinDir_, userDir_;
    std::vector<PresetEntry> entries_;
};

} // namespace ssao
