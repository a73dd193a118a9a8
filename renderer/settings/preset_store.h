// Presets by name, for the app and `ssaolab render` alike: the shipped seed presets (read-only,
// listed first, assets/presets) and the user's own, saved as preset JSON files in a folder
// (SSAOLAB_PRESET_DIR, else $XDG_CONFIG_HOME/ssaolab/presets, else ~/.config/ssaolab/presets; an
// empty variable counts as unset: util/user_dirs.h).
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
    // The shipped presets of this installation and `userDir` (empty: defaultUserDir()).
    static PresetStore standard(const std::string& userDir = "");
    static std::string defaultUserDir();

    // A file path that exists, else the preset named so (seed presets first, then the user's);
    // throws ssao::Error saying where it looked.
    std::string resolve(const std::string& nameOrPath) const;
    // resolve() + read; a named preset gets its name from the store.
    Preset open(const std::string& nameOrPath) const;

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
