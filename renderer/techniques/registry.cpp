// The list of AO techniques: the built-ins, then the user's (techniques/user/). Adding a built-in:
// its folder, one member in technique_settings.h and one entry in builtins().
#include "techniques/registry.h"

#include "techniques/gtao/technique.h"
#include "techniques/hbao/technique.h"
#include "techniques/kernel/technique.h"
#include "techniques/sao/technique.h"
#include "techniques/technique.h"
#include "techniques/technique_settings.h"
#include "techniques/user/user_technique.h"
#include "techniques/vbao/technique.h"
#include "util/error.h"

#include "../../shaders/include/adaptive.h"

#include <algorithm>
#include <atomic>
#include <mutex>

namespace ssao {

const char* const kDefaultTechnique = "kernel"; // what a new Settings{} runs (base/shared_settings.h)

namespace {

// One set of techniques and what the parameter table needs of them. Generations are kept for the
// program's life (a handful: one per user edit adopted), so a list or row handed out stays valid.
struct Generation {
    unsigned number = 0;
    std::vector<TechniqueInfo> list;
    std::vector<TechniqueRows> rows;
    std::vector<std::pair<std::string, std::string>> refused;
};

std::vector<TechniqueInfo> builtins() {
    return {kernelTechnique(), saoTechnique(), hbaoTechnique(), gtaoTechnique(), vbaoTechnique()};
}

std::unique_ptr<Generation> makeGeneration(unsigned number, std::vector<TechniqueInfo> list,
                                           std::vector<std::pair<std::string, std::string>> refused) {
    auto g = std::make_unique<Generation>();
    g->number = number;
    g->list = std::move(list);
    g->refused = std::move(refused);
    for (const auto& t : g->list)
        g->rows.push_back({t.id, t.params(), bool(t.adaptive), t.deinterleave, t.secondLayer, t.file, t.version});
    return g;
}

std::mutex generationsMutex;
std::vector<std::unique_ptr<Generation>>& kept() {
    static std::vector<std::unique_ptr<Generation>> all;
    return all;
}

std::atomic<const Generation*>& currentSlot() {
    static std::atomic<const Generation*> slot{[] {
        std::lock_guard<std::mutex> lock(generationsMutex);
        kept().push_back(makeGeneration(0, builtins(), {}));
        return kept().back().get();
    }()};
    return slot;
}

const Generation& current() {
    return *currentSlot().load(std::memory_order_acquire);
}

} // namespace

const std::vector<TechniqueInfo>& techniques() {
    return current().list;
}

std::vector<std::string> builtinTechniqueIds() {
    std::vector<std::string> ids;
    for (const auto& t : techniques())
        if (t.file.empty()) ids.push_back(t.id);
    return ids;
}

std::vector<std::string> userTechniqueIds() {
    std::vector<std::string> ids;
    for (const auto& t : techniques())
        if (!t.file.empty()) ids.push_back(t.id);
    return ids;
}

const TechniqueInfo& findTechnique(const std::string& id) {
    const Generation& g = current();
    std::string known;
    for (const auto& t : g.list) {
        if (t.id == id) return t;
        known += (known.empty() ? "" : "|") + t.id;
    }
    for (const auto& [refusedId, why] : g.refused)
        if (refusedId == id) throw Error("technique " + id + " was not loaded: " + why);
    throw Error("unknown AO technique '" + id + "' (known: " + known + ")");
}

void setUserTechniques(const std::vector<std::shared_ptr<const UserTechnique>>& loaded,
                       const std::vector<std::pair<std::string, std::string>>& refused) {
    std::vector<TechniqueInfo> list = builtins();
    for (const auto& t : loaded)
        list.push_back(userTechniqueInfo(t));
    auto& slot = currentSlot();
    std::lock_guard<std::mutex> lock(generationsMutex);
    kept().push_back(makeGeneration(slot.load()->number + 1, std::move(list), refused));
    slot.store(kept().back().get(), std::memory_order_release);
}

unsigned techniquesGeneration() {
    return current().number;
}

std::string refusedTechniqueReason(const std::string& id) {
    for (const auto& [refusedId, why] : current().refused)
        if (refusedId == id) return why;
    return "";
}

const std::vector<std::pair<std::string, std::string>>& refusedUserTechniques() {
    return current().refused;
}

// What the settings need of the techniques (techniques/registry.h), from the modules.
const std::vector<TechniqueRows>& registeredTechniques() {
    return current().rows;
}

std::string unphysicalReason(const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    return t.unphysical ? t.unphysical(s) : std::string();
}

bool usesPyramid(const Settings& s) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    return t.pyramid && t.pyramid(s);
}

bool deinterleaves(const Settings& s) {
    return s.ao.deinterleave && findTechnique(s.ao.technique).deinterleave && s.ao.resolution == AoResolution::Full &&
           !usesPyramid(s) && s.gbuffer.guardBandPx == 0 && !s.gbuffer.backFaces && !s.gbuffer.secondLayer && s.ao.normals == NormalSource::GBuffer;
}

DenoiseSettings effectiveDenoise(const Settings& s) {
    if (s.denoise.kind != DenoiseKind::Auto) return s.denoise;
    DenoiseSettings d = findTechnique(s.ao.technique).denoiser;
    d.upsample = s.denoise.upsample; // how reduced AO returns to full size stays the user's choice
    return d;
}

double adaptiveShare(const Settings& s, float radiusPx) {
    const TechniqueInfo& t = findTechnique(s.ao.technique);
    if (!s.ao.adaptive || !t.adaptive) return 1.0;
    const AdaptiveCount c = t.adaptive(s);
    if (c.full <= 0) return 1.0;
    const float r = std::max(radiusPx, 0.0f);
    const int n = c.march ? gpu::adaptiveSteps(s.ao.adaptivePx, c.full, r)
                          : gpu::adaptiveSamples(s.ao.adaptivePx, c.full, r);
    return double(n) / double(c.full);
}

} // namespace ssao
