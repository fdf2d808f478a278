#pragma once
// Follows the identity (in the sense of the uniform Loop oracle) of every live vertex of an RGB mesh
// through the mesh observer: base vertex i is identity i, and a vertex reported as inserted on the
// edge (a, b) is the oracle's midpoint of their identities. Vertex slots are reused after removal,
// so the map is rewritten on every vertex_added and cleared on vertex_removed.
#include <set>
#include <vector>

#include "rgb/mesh/observer.h"
#include "support/uniform_loop_oracle.h"

namespace rgbtest {

class IdentityTracker : public rgb::MeshObserver {
public:
    static constexpr Identity kNone = 0xffffffffu;

    IdentityTracker(rgb::Mesh& mesh, const UniformLoopOracle& oracle);
    ~IdentityTracker() override;
    IdentityTracker(const IdentityTracker&) = delete;
    IdentityTracker& operator=(const IdentityTracker&) = delete;

    const UniformLoopOracle& oracle() const { return oracle_; }
    Identity identity(rgb::VertexId v) const { return v.idx < identity_.size() ? identity_[v.idx] : kNone; }
    IdentityTriangle identity_triangle(rgb::FaceId f) const;
    // The live vertex with this identity, if any (linear search: for tests on small meshes).
    rgb::VertexId vertex_of(Identity id) const;
    // The identities of all live vertices: the vertex set of the mesh, comparable across histories.
    std::set<Identity> live_identities() const;

    void vertex_added(const rgb::Mesh& mesh, rgb::VertexId v, rgb::VertexId a, rgb::VertexId b) override;
    void vertex_removed(const rgb::Mesh& mesh, rgb::VertexId v) override;

private:
    rgb::Mesh& mesh_;
    const UniformLoopOracle& oracle_;
    std::vector<Identity> identity_;  // by vertex slot
};

// Records every change the mesh reports, in order, until cleared.
class ChangeRecorder : public rgb::MeshObserver {
public:
    explicit ChangeRecorder(rgb::Mesh& mesh);
    ~ChangeRecorder() override;
    ChangeRecorder(const ChangeRecorder&) = delete;
    ChangeRecorder& operator=(const ChangeRecorder&) = delete;

    void clear();
    std::vector<rgb::VertexId> vertices_added, vertices_removed;
    std::vector<rgb::FaceId> faces_added, faces_removed;

    void vertex_added(const rgb::Mesh&, rgb::VertexId v, rgb::VertexId, rgb::VertexId) override { vertices_added.push_back(v); }
    void vertex_removed(const rgb::Mesh&, rgb::VertexId v) override { vertices_removed.push_back(v); }
    void face_added(const rgb::Mesh&, rgb::FaceId f) override { faces_added.push_back(f); }
    void face_removed(const rgb::Mesh&, rgb::FaceId f) override { faces_removed.push_back(f); }

private:
    rgb::Mesh& mesh_;
};

}  // namespace rgbtest
