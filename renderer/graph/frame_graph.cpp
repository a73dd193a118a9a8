#include "graph/frame_graph.h"

#include "scene/camera.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace ssao {

int scaledSize(int base, float scale) {
    return std::max(1, int(std::ceil(double(base) * double(scale) - 1e-9)));
}

bool isDepthFormat(GLenum f) {
    return f == GL_DEPTH_COMPONENT32F || f == GL_DEPTH_COMPONENT24 || f == GL_DEPTH_COMPONENT16;
}

gpu::FrameConstants withoutFrameIndex(gpu::FrameConstants c) {
    c.clip.w = 0.0f;
    return c;
}

PassDecl FrameGraph::declare(const Pass& p, const Settings& s) {
    PassDecl d;
    PassBuilder b(d);
    p.setup(b, s);
    return d;
}

std::vector<size_t> FrameGraph::order(const std::vector<std::string>& names,
                                      const std::vector<PassDecl>& decls) {
    std::map<std::string, size_t> producer;
    for (size_t i = 0; i < decls.size(); ++i)
        for (const auto& w : decls[i].writes) {
            auto [it, fresh] = producer.emplace(w.name, i);
            if (!fresh)
                throw Error("frame graph: resource '" + w.name + "' is written by both '" +
                            names[it->second] + "' and '" + names[i] + "'");
        }
    // deps[i]: the producers node i waits for.
    std::vector<std::set<size_t>> deps(decls.size());
    for (size_t i = 0; i < decls.size(); ++i)
        for (const auto& r : decls[i].reads) {
            auto it = producer.find(r);
            if (it == producer.end())
                throw Error("frame graph: pass '" + names[i] + "' reads '" + r + "', which no pass writes");
            if (it->second == i)
                throw Error("frame graph: pass '" + names[i] + "' reads its own output '" + r +
                            "' (a cycle)");
            deps[i].insert(it->second);
        }
    // Kahn's algorithm, always taking the earliest-registered ready node: a stable, readable order.
    std::vector<size_t> out;
    std::vector<bool> done(decls.size(), false);
    while (out.size() < decls.size()) {
        size_t pick = decls.size();
        for (size_t i = 0; i < decls.size() && pick == decls.size(); ++i) {
            if (done[i]) continue;
            bool ready = true;
            for (size_t d : deps[i])
                ready &= bool(done[d]);
            if (ready) pick = i;
        }
        if (pick == decls.size()) {
            // Every remaining node waits on another remaining one: walk the waits to name the cycle.
            size_t at = 0;
            while (done[at])
                ++at;
            std::vector<size_t> path;
            while (std::find(path.begin(), path.end(), at) == path.end()) {
                path.push_back(at);
                for (size_t d : deps[at])
                    if (!done[d]) {
                        at = d;
                        break;
                    }
            }
            std::string text;
            std::string via;
            for (auto it = std::find(path.begin(), path.end(), at); it != path.end(); ++it)
                text += "'" + names[*it] + "' <- ";
            text += "'" + names[at] + "'";
            for (const auto& r : decls[path.back()].reads)
                if (producer.count(r) && producer[r] == at) via = r;
            throw Error("frame graph: cycle " + text + " (through resource '" + via + "')");
        }
        done[pick] = true;
        out.push_back(pick);
    }
    return out;
}

std::string FrameGraph::resolve(const std::string& name) const {
    std::string n = name;
    for (int hops = 0; hops < 16; ++hops) {
        auto it = aliases_.find(n);
        if (it == aliases_.end()) return n;
        n = it->second;
    }
    throw Error("frame graph: alias loop at '" + name + "'");
}

void FrameGraph::compile(const std::vector<Node>& nodes, const std::map<std::string, std::string>& aliases,
                         int w, int h) {
    aliases_ = aliases;
    std::vector<std::string> names;
    std::vector<PassDecl> decls;
    for (const Node& n : nodes) {
        names.push_back(n.pass->name());
        decls.push_back(declare(*n.pass, *n.settings));
        for (auto& r : decls.back().reads)
            r = resolve(r);
    }
    const std::vector<size_t> idx = order(names, decls);
    nodes_.clear();
    order_.clear();
    for (size_t i : idx) {
        nodes_.push_back({nodes[i].pass, nodes[i].settings, decls[i]});
        order_.push_back(names[i]);
    }
    // Allocate (or keep) every declared resource; free the ones no pass writes any more.
    std::set<std::string> live;
    for (const Compiled& n : nodes_)
        for (const ResourceDesc& d : n.decl.writes) {
            live.insert(d.name);
            const auto [sw, sh] = displaySize(scaledSize(w, d.scale), scaledSize(h, d.scale), d.maxWidth);
            const int rw = sw + 2 * d.margin, rh = sh + 2 * d.margin;
            Resource& r = resources_[d.name];
            r.producer = n.pass->name();
            int levels = 1;
            while (levels < d.levels && std::max(rw, rh) >> levels > 0)
                ++levels;
            auto fits = [&](const gl::Texture2D& t) {
                return t && t.width() == rw && t.height() == rh && t.format() == d.format && t.levels() == levels;
            };
            if (!fits(r.texture)) {
                gl::Texture2D& spare = spares_[d.name];
                gl::Texture2D before = std::move(r.texture);
                r.texture = fits(spare) ? std::move(spare) : gl::Texture2D(rw, rh, d.format, d.name, levels);
                spare = std::move(before); // kept for the way back (its contents are stale: version 0)
                r.generation = nextGeneration_++;
                r.version = 0;
            }
            r.desc = d;
        }
    for (auto it = resources_.begin(); it != resources_.end();)
        it = live.count(it->first) ? std::next(it) : resources_.erase(it);
    for (auto it = spares_.begin(); it != spares_.end();)
        it = live.count(it->first) ? std::next(it) : spares_.erase(it);
    // Framebuffers of outputs that went away (they would keep the textures alive), and the keys
    // and timers of passes that left the graph.
    for (auto it = fbos_.begin(); it != fbos_.end();) {
        bool alive = true;
        size_t at = it->first.find('|');
        while (at != std::string::npos && alive) {
            const size_t next = it->first.find('|', at + 1);
            alive = live.count(
                it->first.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
            at = next;
        }
        if (alive) {
            ++it;
        } else {
            fboGenerations_.erase(it->first);
            it = fbos_.erase(it);
        }
    }
    auto inGraph = [&](const std::string& pass) {
        return std::count(order_.begin(), order_.end(), pass) > 0;
    };
    for (auto it = keys_.begin(); it != keys_.end();)
        it = inGraph(it->first) ? std::next(it) : keys_.erase(it);
    for (auto it = timers_.begin(); it != timers_.end();)
        it = inGraph(it->first) ? std::next(it) : timers_.erase(it);
}

namespace {
// Ends the timer query and the debug group even when a pass throws (e.g. a shader variant that
// does not compile after a hot reload), so the next frame starts from a clean GL state.
struct PassScope {
    gl::GpuTimer& timer;
    PassScope(gl::GpuTimer& t, const std::string& name) : timer(t) {
        glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name.c_str());
        timer.begin();
    }
    ~PassScope() {
        timer.end();
        glPopDebugGroup();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;
};
} // namespace

FrameReport FrameGraph::execute(const FrameInfo& frame, gl::ShaderLibrary& shaders,
                                const gl::FullscreenTriangle& tri, const std::function<void()>& submitted) {
    FrameReport report;
    std::vector<gl::GpuTimer*> timers;
    // Demand: walk back from what is wanted; a pass is live when something needed is its output.
    std::vector<char> live(nodes_.size(), 1);
    needed_.clear();
    if (wanted_) {
        for (const auto& w : *wanted_)
            needed_.insert(resolve(w));
        for (size_t i = nodes_.size(); i-- > 0;) {
            bool l = false;
            for (const auto& w : nodes_[i].decl.writes)
                l = l || needed_.count(w.name) > 0;
            live[i] = l;
            if (l)
                for (const auto& r : nodes_[i].decl.reads)
                    needed_.insert(resolve(r));
        }
    }
    for (size_t i = 0; i < nodes_.size(); ++i) {
        Compiled& n = nodes_[i];
        const std::string& name = n.pass->name();
        if (!live[i]) {
            PassReport culled{name};
            culled.culled = true;
            report.passes.push_back(culled);
            timers.push_back(nullptr);
            continue;
        }
        // Its config (the pass's pure function of the settings and the frame) and the state of
        // everything it reads and writes.
        RunKey key{n.pass->configure(*n.settings, frame), {}};
        for (const auto& r : n.decl.reads)
            key.inputs.push_back(get(r).version);
        for (const auto& w : n.decl.writes)
            key.inputs.push_back(get(w.name).generation);
        key.inputs.push_back(n.pass->externalVersion());
        PassReport pr{name};
        auto it = keys_.find(name);
        // Also re-run when an output it left unwritten (nobody wanted it then) is needed now.
        bool missing = false;
        if (it != keys_.end())
            for (const auto& w : n.decl.writes)
                missing = missing || (needed(w.name) && !written_[name].count(w.name));
        if (it == keys_.end() || !(it->second == key) || missing) {
            gl::GpuTimer& t = timers_[name];
            keys_.erase(name); // a pass that throws half-way has no valid output: run it again next time
            unwritten_.clear();
            {
                PassScope scope(t, name);
                PassContext ctx(*this, key.config, frame.scene, shaders, tri, name);
                n.pass->execute(ctx);
            }
            std::set<std::string>& written = written_[name];
            written.clear();
            for (const auto& w : n.decl.writes) {
                resources_.at(w.name).version = nextVersion_++;
                if (!unwritten_.count(w.name)) written.insert(w.name);
            }
            pr.counters = n.pass->counters();
            keys_[name] = std::move(key);
            pr.ran = true;
            timers.push_back(&t);
        } else {
            timers.push_back(nullptr);
        }
        report.passes.push_back(pr);
    }
    if (submitted) submitted();
    for (size_t i = 0; i < timers.size(); ++i)
        if (timers[i]) report.passes[i].gpuMs = timers[i]->resultMs();
    return report;
}

std::vector<const Resource*> FrameGraph::resources(bool includeInternal) const {
    std::vector<const Resource*> out;
    for (const Compiled& n : nodes_)
        for (const auto& w : n.decl.writes) {
            const Resource& r = resources_.at(w.name);
            if (includeInternal || !r.desc.internal) out.push_back(&r);
        }
    return out;
}

const Resource* FrameGraph::find(const std::string& name) const {
    auto it = resources_.find(resolve(name));
    return it == resources_.end() ? nullptr : &it->second;
}

const Resource& FrameGraph::get(const std::string& name) const {
    const Resource* r = find(name);
    if (!r) throw Error("frame graph: no resource named '" + name + "'");
    return *r;
}

const PassDecl* FrameGraph::declaration(const std::string& pass) const {
    for (const Compiled& n : nodes_)
        if (n.pass->name() == pass) return &n.decl;
    return nullptr;
}

Pass* FrameGraph::pass(const std::string& name) const {
    for (const Compiled& n : nodes_)
        if (n.pass->name() == name) return n.pass;
    return nullptr;
}

const ConfigKey* FrameGraph::lastConfig(const std::string& pass) const {
    auto it = keys_.find(pass);
    return it == keys_.end() ? nullptr : &it->second.config;
}

const Settings* FrameGraph::settingsOf(const std::string& pass) const {
    for (const Compiled& n : nodes_)
        if (n.pass->name() == pass) return n.settings;
    return nullptr;
}

void FrameGraph::bindOutputs(const std::string& pass, const std::vector<std::string>& names) {
    std::string key = pass;
    std::vector<unsigned> gens;
    for (const auto& n : names) {
        key += "|" + n;
        gens.push_back(get(n).generation);
    }
    auto it = fbos_.find(key);
    if (it == fbos_.end() || fboGenerations_[key] != gens) {
        std::vector<const gl::Texture2D*> colors;
        const gl::Texture2D* depth = nullptr;
        for (const auto& n : names) {
            const Resource& r = get(n);
            if (isDepthFormat(r.desc.format))
                depth = &r.texture;
            else
                colors.push_back(&r.texture);
        }
        fbos_[key] = gl::Framebuffer(colors, depth, key);
        fboGenerations_[key] = gens;
        it = fbos_.find(key);
    }
    it->second.bind();
}

// ---- PassContext ----------------------------------------------------------------------------

namespace {
bool declared(const PassDecl* d, const std::string& name) {
    if (!d) return false;
    for (const auto& r : d->reads)
        if (r == name) return true;
    for (const auto& w : d->writes)
        if (w.name == name) return true;
    return false;
}
} // namespace

const gl::Texture2D& PassContext::in(const std::string& name) const {
    const std::string r = graph_.resolve(name);
    if (!declared(graph_.declaration(pass_), r))
        throw Error("pass '" + pass_ + "' uses '" + name + "' without declaring it");
    return graph_.get(r).texture;
}

const ResourceDesc& PassContext::desc(const std::string& name) const {
    return graph_.get(name).desc;
}

void PassContext::bindOutputs(const std::vector<std::string>& names) const {
    for (const auto& n : names)
        if (!declared(graph_.declaration(pass_), n))
            throw Error("pass '" + pass_ + "' writes '" + n + "' without declaring it");
    graph_.bindOutputs(pass_, names);
}

bool PassContext::needed(const std::string& output) const {
    return graph_.needed(output);
}

void PassContext::leaveUnwritten(const std::string& output) const {
    graph_.leaveUnwritten(output);
}

glm::ivec2 PassContext::size(const std::string& name) const {
    const Resource& r = graph_.get(name);
    return {r.width(), r.height()};
}

void PassContext::drawFullscreen() const {
    triangle_.draw();
}

const char* tapStateName(TapState s) {
    switch (s) {
    case TapState::Open:
        return "open";
    case TapState::Occluded:
        return "occluded";
    case TapState::BehindEye:
        return "behind eye";
    case TapState::Offscreen:
        return "off screen";
    case TapState::Sky:
        return "sky";
    }
    return "?";
}

} // namespace ssao
