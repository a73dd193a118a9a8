// The frame graph: passes declare what they read and write (graph/pass.h); compile() orders them
// so producers run first and allocates every resource at its declared size; execute() runs a pass
// only when its key changed — its config (graph/pass_config.h: derived from the settings and the
// frame by the pass's own pure function), the versions of the resources it reads, the generations
// of those it writes and the version of its external data. A missing producer, two producers of
// one resource or a cycle is an ssao::Error naming the resource.
#pragma once
#include "gl/resources.h"
#include "graph/frame_report.h"
#include "graph/pass.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ssao {

class FrameGraph {
  public:
    struct Node {
        Pass* pass;
        const Settings* settings; // of the pass's branch
    };

    // Declares every node (setup), resolves reads through `aliases` (name → the resource it
    // stands for), orders the nodes and (re)allocates resources for a base size of w x h.
    // The settings must stay alive and unchanged until the next compile().
    void compile(const std::vector<Node>& nodes, const std::map<std::string, std::string>& aliases, int w,
                 int h);
    // `submitted`, when given, runs once every pass's GL work is issued and before the timers are
    // read (the renderer's frame time limit waits there).
    FrameReport execute(const FrameInfo& frame, gl::ShaderLibrary& shaders, const gl::FullscreenTriangle& tri,
                        const std::function<void()>& submitted = {});
    // Forgets every pass key: the next execute() runs every pass.
    void invalidate() { keys_.clear(); }
    // The resources read from outside the graph (shown, written to disk, judged); nullopt = every
    // resource. A pass none of whose outputs is wanted, directly or through the passes that read
    // them, is culled; PassContext::needed() tells a pass which of its outputs are.
    void setWanted(std::optional<std::set<std::string>> wanted) { wanted_ = std::move(wanted); }
    const std::optional<std::set<std::string>>& wanted() const { return wanted_; }
    // Whether the resource holds this frame's content: the last execute() needed it. One nothing
    // wanted (a culled pass's output, a target left unwritten) may hold an older frame's.
    bool current(const std::string& resource) const { return needed(resource); }

    // Pure ordering (testable without GL): the node indices in execution order.
    static std::vector<size_t> order(const std::vector<std::string>& names,
                                     const std::vector<PassDecl>& decls);
    static PassDecl declare(const Pass& p, const Settings& s);

    const std::vector<std::string>& passOrder() const { return order_; }
    // Resources in the order their producers run; internal ones only when asked.
    std::vector<const Resource*> resources(bool includeInternal = false) const;
    const Resource* find(const std::string& name) const; // follows aliases; null if unknown
    const Resource& get(const std::string& name) const;  // throws naming the resource
    const PassDecl* declaration(const std::string& pass) const;
    Pass* pass(const std::string& name) const;
    const Settings* settingsOf(const std::string& pass) const;
    // The config the pass's last run used (for the inspector's replay); null before its first run.
    const ConfigKey* lastConfig(const std::string& pass) const;
    std::string resolve(const std::string& name) const;

    // Used by PassContext.
    void bindOutputs(const std::string& pass, const std::vector<std::string>& names);
    bool needed(const std::string& resource) const { return !wanted_ || needed_.count(resolve(resource)) > 0; }
    void leaveUnwritten(const std::string& resource) { unwritten_.insert(resolve(resource)); }

  private:
    struct Compiled {
        Pass* pass;
        const Settings* settings;
        PassDecl decl;
    };
    // What a pass's output was made from: its config and the state of everything it reads.
    struct RunKey {
        ConfigKey config;
        std::vector<uint64_t> inputs; // read versions, write generations, external version
        bool operator==(const RunKey& o) const { return config == o.config && inputs == o.inputs; }
    };
    std::vector<Compiled> nodes_; // in execution order
    std::vector<std::string> order_;
    std::map<std::string, std::string> aliases_;
    std::map<std::string, Resource> resources_;
    // Per resource, its texture of the size before the last change: the app's moving and still
    // frames take turns at two sizes, and a texture made anew is memory the CPU rasteriser touches
    // for the first time (a page fault on every first touch).
    std::map<std::string, gl::Texture2D> spares_;
    std::map<std::string, RunKey> keys_;          // pass name → key of its last run
    std::map<std::string, std::set<std::string>> written_; // pass name → outputs its last run wrote
    std::optional<std::set<std::string>> wanted_;
    std::set<std::string> needed_, unwritten_; // during execute()
    std::map<std::string, gl::GpuTimer> timers_;  // pass name → timer
    std::map<std::string, gl::Framebuffer> fbos_; // "pass|out1|out2" → framebuffer
    std::map<std::string, std::vector<unsigned>> fboGenerations_;
    uint64_t nextVersion_ = 1;
    unsigned nextGeneration_ = 1; // graph-wide: a re-created resource never reuses a generation
};

} // namespace ssao
