#pragma once
// Steps the request layer's operations share (requests.cpp, lod_criteria.cpp, the LOD driver), each
// written once: the observer that counts a request's operators and collects the faces they create,
// removing a set of vertices finest first with what depends on them, the vertices above a level
// by level, and the check of a request's ball.
#include <cstddef>
#include <optional>
#include <vector>

#include "rgb/lod/requests.h"
#include "rgb/mesh/handles.h"
#include "rgb/mesh/observer.h"

namespace rgb {

class Mesh;

// Counts splits and removals, and collects the faces each operator creates (for the caller's work
// list), for as long as it lives.
class OperatorLog : public MeshObserver {
public:
    explicit OperatorLog(Mesh& mesh);
    ~OperatorLog() override;
    OperatorLog(const OperatorLog&) = delete;
    OperatorLog& operator=(const OperatorLog&) = delete;

    void vertex_added(const Mesh&, VertexId, VertexId, VertexId) override { ++splits; }
    void vertex_removed(const Mesh&, VertexId) override { ++removals; }
    void face_added(const Mesh&, FaceId f) override { added.push_back(f); }

    std::size_t splits = 0, removals = 0;
    std::vector<FaceId> added;

private:
    Mesh& mesh_;
};

// Removes every vertex of `doomed` (and whatever cannot exist without one of them), finest first, so
// that each is removable when its turn comes. One may already be gone as the dependent of another:
// removals add no vertices, so a slot that is still live is still the same vertex. The result does not
// depend on the order of `doomed`.
void remove_finest_first(Mesh& mesh, std::vector<VertexId> doomed);

// The vertices of level above `level`, by level (index: the level; within one, in slot order). Removed
// finest level first, each is removable when its turn comes.
std::vector<std::vector<VertexId>> vertices_above_by_level(const Mesh& mesh, int level);

// Throws std::invalid_argument unless the ball (if any) has a finite centre and a positive, finite
// radius.
void check_sphere(const std::optional<Sphere>& sphere);

}  // namespace rgb
