#include "scene/gpu/occlusion_culler.h"

#include "scene/gpu/gpu_scene.h"

#include "../../../shaders/include/box_corners.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

namespace ssao {

const int OcclusionCuller::kBoxCorners[36] = {SSAO_BOX_CORNERS};

Bounds OcclusionCuller::grown(const Bounds& b) {
    const glm::vec3 big = glm::max(glm::abs(b.min), glm::abs(b.max));
    const float pad = 1e-4f * glm::length(b.max - b.min) + 1e-5f * std::max({big.x, big.y, big.z});
    Bounds g;
    g.min = b.min - glm::vec3(pad);
    g.max = b.max + glm::vec3(pad);
    return g;
}

void OcclusionCuller::begin(size_t draws, unsigned scene, GLuint boxProgram) {
    boxProgram_ = boxProgram;
    if (!emptyVao_) emptyVao_ = gl::VertexArray("occlusion-box");
    if (scene != scene_ || visible_.size() != draws) {
        scene_ = scene;
        visible_.assign(draws, 1); // nothing known: everything in phase 1
        pending_.assign(draws, 0);
    }
    while (queries_.size() < draws) {
        GLuint id = 0;
        glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &id);
        queries_.emplace_back(id);
    }
    // The last run's answers: a draw none of whose fragments passed the depth test was hidden by
    // what came before it. An answer not in yet (a GPU with frames queued) is not waited for: the
    // draw keeps its flag, which only orders the work, and its query waits for the next run.
    for (size_t i = 0; i < draws; ++i) {
        if (!pending_[i]) continue;
        GLuint ready = 0, any = 1;
        glGetQueryObjectuiv(queries_[i].id(), GL_QUERY_RESULT_AVAILABLE, &ready);
        if (!ready) continue;
        glGetQueryObjectuiv(queries_[i].id(), GL_QUERY_RESULT, &any);
        visible_[i] = any != 0;
        pending_[i] = 0;
    }
}

void OcclusionCuller::beginDraw(size_t draw) {
    current_ = draw;
    queried_ = !pending_[draw]; // its last answer still unread: no second query on the same object
    if (queried_) glBeginQuery(GL_ANY_SAMPLES_PASSED, queries_[draw].id());
}

void OcclusionCuller::endDraw() {
    if (!queried_) return;
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    pending_[current_] = 1;
}

std::vector<bool> OcclusionCuller::testBoxes(const std::vector<Bounds>& boxes, const glm::mat4& viewProj,
                                             bool zeroToOneDepth) {
    std::vector<bool> shown(boxes.size(), true);
    while (boxQueries_.size() < boxes.size()) {
        GLuint id = 0;
        glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &id);
        boxQueries_.emplace_back(id);
    }
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_CULL_FACE); // the eye is outside every box tested: its front faces are the nearest
    glCullFace(GL_BACK);
    glUseProgram(boxProgram_);
    glBindVertexArray(emptyVao_.id());
    std::vector<uint8_t> tested(boxes.size(), 0);
    tested_ = 0;
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Bounds g = grown(boxes[i]);
        // A box the near plane reaches (the eye may be inside it) is taken as shown.
        if (!boxes[i].valid() || !beyondNearPlane(g, viewProj, zeroToOneDepth)) continue;
        glUniform3fv(1, 1, glm::value_ptr(g.min));
        glUniform3fv(2, 1, glm::value_ptr(g.max));
        glBeginQuery(GL_ANY_SAMPLES_PASSED, boxQueries_[i].id());
        glDrawArrays(GL_TRIANGLES, 0, 36);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        tested[i] = 1;
        ++tested_;
    }
    glDepthMask(GL_TRUE); // the G-buffer's state (SceneDrawState): writes on, no face culling
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_CULL_FACE);
    glUseProgram(0); // the scene's draws bind theirs
    for (size_t i = 0; i < boxes.size(); ++i) {
        if (!tested[i]) continue;
        GLuint any = 1;
        glGetQueryObjectuiv(boxQueries_[i].id(), GL_QUERY_RESULT, &any);
        shown[i] = any != 0;
    }
    return shown;
}

} // namespace ssao
