#include "settings/preset_store.h"

#include "util/paths.h"

#include "util/closest_name.h"
#include "util/error.h"
#include "util/user_dirs.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace ssao {

PresetStore::PresetStore(std::string builtinDir, std::string userDir)
    : builtinDir_(std::move(builtinDir)), userDir_(std::move(userDir)) {
    refresh();
}

PresetStore PresetStore::standard(const std::string& userDir) {
    return PresetStore(assetRoot() + "/presets", userDir.empty() ? defaultUserDir() : userDir);
}

std::string PresetStore::resolve(const std::string& nameOrPath) const {
    std::error_code ec;
    if (fs::is_regular_file(nameOrPath, ec)) return nameOrPath;
    if (const PresetEntry* e = find(nameOrPath)) return e->path;
    if (nameOrPath.find('/') != std::string::npos || fs::path(nameOrPath).extension() == ".json")
        throw Error("preset file not found: " + nameOrPath);
    std::vector<std::string> names;
    for (const auto& e : entries_)
        names.push_back(e.name);
    throw Error("no preset named '" + nameOrPath + "'" + didYouMean(nameOrPath, names) + " (looked in " + builtinDir_ +
                " and " + userDir_ + ")");
}

Preset PresetStore::open(const std::string& nameOrPath) const {
    const std::string path = resolve(nameOrPath);
    Preset p = readPresetFile(path);
    if (find(nameOrPath)) p.name = nameOrPath;
    return p;
}

std::string PresetStore::defaultUserDir() {
    if (const std::string d = envValue("SSAOLAB_PRESET_DIR"); !d.empty()) return d;
    if (const std::string x = xdgUserDir("XDG_CONFIG_HOME", ".config"); !x.empty()) return x + "/presets";
    return "ssaolab-presets";
}

void PresetStore::refresh() {
    entries_.clear();
    auto scan = [&](const std::string& dir, bool builtin) {
        std::vector<PresetEntry> found;
        std::error_code ec;
        for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator();
             it.increment(ec))
            if (it->path().extension() == ".json")
                found.push_back({it->path().stem().string(), it->path().string(), builtin});
        std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.name < b.name; });
        entries_.insert(entries_.end(), found.begin(), found.end());
    };
    scan(builtinDir_, true);
    scan(userDir_, false);
}

const PresetEntry* PresetStore::find(const std::string& name) const {
    for (const auto& e : entries_)
        if (e.name == name) return &e;
    return nullptr;
}

Preset PresetStore::load(const std::string& name) const {
    const PresetEntry* e = find(name);
    if (!e) throw Error("no preset named '" + name + "'");
    Preset p = readPresetFile(e->path);
    p.name = name;
    return p;
}

void PresetStore::checkName(const std::string& name) const {
    if (name.empty()) throw Error("a preset needs a name");
    for (char c : name)
        if (!(std::isalnum((unsigned char)c) || c == ' ' || c == '_' || c == '-' || c == '.'))
            throw Error("preset name '" + name + "' may only use letters, digits, space, _ - .");
    if (name.front() == '.' || name.front() == ' ')
        throw Error("preset name '" + name + "' must start with a letter or digit");
    if (const PresetEntry* e = find(name); e && e->builtin)
        throw Error("'" + name + "' is a built-in preset; choose another name");
}

std::string PresetStore::save(const Preset& p) {
    checkName(p.name);
    const std::string path = (fs::path(userDir_) / (p.name + ".json")).string();
    writePresetFile(p, path);
    refresh();
    return path;
}

void PresetStore::rename(const std::string& from, const std::string& to) {
    const PresetEntry* e = find(from);
    if (!e) throw Error("no preset named '" + from + "'");
    if (e->builtin) throw Error("'" + from + "' is a built-in preset and cannot be renamed");
    checkName(to);
    if (find(to)) throw Error("a preset named '" + to + "' already exists");
    Preset p = readPresetFile(e->path);
    p.name = to;
    writePresetFile(p, (fs::path(userDir_) / (to + ".json")).string());
    fs::remove(e->path);
    refresh();
}

void PresetStore::remove(const std::string& name) {
    const PresetEntry* e = find(name);
    if (!e) throw Error("no preset named '" + name + "'");
    if (e->builtin) throw Error("'" + name + "' is a built-in preset and cannot be deleted");
    fs::remove(e->path);
    refresh();
}

} // namespace ssao
