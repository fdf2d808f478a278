#include "app/auto_lod.h"

#include <algorithm>
#include <queue>
#include <vector>

#include <glm/geometric.hpp>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/observer.h"
#include "rgb/refine.h"

namespace app {
namespace {

struct Candidate {
    double length = 0.0;
    rgb::FaceId face;
    friend bool operator<(const Candidate& a, const Candidate& b) {
        return a.length != b.length ? a.length < b.length : b.face < a.face;  // deterministic ties
    }
};

double longest_edge(const rgb::Mesh& mesh, rgb::FaceId f) {
    const auto& v = mesh.face_vertices(f);
    const glm::dvec3 p0 = rgb::displayed_position(mesh, v[0]);
    const glm::dvec3 p1 = rgb::displayed_position(mesh, v[1]);
    const glm::dvec3 p2 = rgb::displayed_position(mesh, v[2]);
    return std::max({glm::distance(p0, p1), glm::distance(p1, p2), glm::distance(p2, p0)});
}

// Faces created by the refinements, to queue them.
struct NewFaces : rgb::MeshObserver {
    std::vector<rgb::FaceId> faces;
    void face_added(const rgb::Mesh&, rgb::FaceId f) override { faces.push_back(f); }
};

}  // namespace

struct AutoLodJob::State {
    State(rgb::Mesh& m, const AutoLodSettings& s) : mesh(m), settings(s) {}
    rgb::Mesh& mesh;
    AutoLodSettings settings;
    double threshold = 0.0;
    std::size_t start_faces = 0;
    std::priority_queue<Candidate> queue;
    NewFaces new_faces;
    bool changed = false;
    bool finished = false;

    void push(rgb::FaceId f) {
        if (mesh.level(f) < settings.max_level) queue.push({longest_edge(mesh, f), f});
    }
};

AutoLodJob::AutoLodJob(rgb::Mesh& mesh, const AutoLodSettings& settings)
    : state_(std::make_unique<State>(mesh, settings)) {
    State& s = *state_;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (rgb::VertexId v : mesh.vertices()) {
        lo = glm::min(lo, rgb::displayed_position(mesh, v));
        hi = glm::max(hi, rgb::displayed_position(mesh, v));
    }
    s.threshold = settings.max_edge_fraction * glm::distance(lo, hi);
    s.start_faces = mesh.num_faces();
    for (rgb::FaceId f : mesh.faces()) s.push(f);
    mesh.add_observer(&s.new_faces);
}

AutoLodJob::~AutoLodJob() { state_->mesh.remove_observer(&state_->new_faces); }

bool AutoLodJob::step(std::chrono::microseconds slice) {
    State& s = *state_;
    const auto deadline = std::chrono::steady_clock::now() + slice;
    while (!s.finished && std::chrono::steady_clock::now() < deadline) {
        for (int batch = 0; batch < 64 && !s.finished; ++batch) {
            if (s.queue.empty() || s.mesh.num_faces() >= s.settings.triangle_budget ||
                s.queue.top().length <= s.threshold) {
                s.finished = true;
                break;
            }
            const Candidate top = s.queue.top();
            s.queue.pop();
            // Entries are never updated in place: a face that died or changed since is stale.
            if (!s.mesh.is_live(top.face) || longest_edge(s.mesh, top.face) != top.length) continue;
            const rgb::HalfedgeId h = rgb::edge_refining_face(s.mesh, top.face);
            if (!h.valid()) continue;
            s.new_faces.faces.clear();
            s.changed |= rgb::refine_edge(s.mesh, s.mesh.from_vertex(h), s.mesh.to_vertex(h));
            for (rgb::FaceId f : s.new_faces.faces)
                if (s.mesh.is_live(f)) s.push(f);
        }
    }
    return !s.finished;
}

float AutoLodJob::progress() const {
    const State& s = *state_;
    if (s.finished) return 1.0f;
    if (s.settings.triangle_budget <= s.start_faces) return 0.0f;
    const double done = static_cast<double>(s.mesh.num_faces()) - static_cast<double>(s.start_faces);
    return static_cast<float>(std::clamp(done / static_cast<double>(s.settings.triangle_budget - s.start_faces), 0.0, 1.0));
}

bool AutoLodJob::changed() const { return state_->changed; }

}  // namespace app
