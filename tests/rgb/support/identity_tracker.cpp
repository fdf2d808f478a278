#include "support/identity_tracker.h"

#include <string>

#include <gtest/gtest.h>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

IdentityTracker::IdentityTracker(rgb::Mesh& mesh, const UniformLoopOracle& oracle) : mesh_(mesh), oracle_(oracle) {
    identity_.assign(mesh.vertex_capacity(), kNone);
    for (rgb::VertexId v : mesh.vertices()) {
        // Only a base mesh can be tracked from scratch: its slots are the oracle's base identities.
        EXPECT_EQ(mesh.level(v), 0) << "IdentityTracker must be attached to a base mesh";
        identity_[v.idx] = v.idx;
    }
    mesh_.add_observer(this);
}

IdentityTracker::~IdentityTracker() { mesh_.remove_observer(this); }

IdentityTriangle IdentityTracker::identity_triangle(rgb::FaceId f) const {
    const auto& v = mesh_.face_vertices(f);
    return {identity(v[0]), identity(v[1]), identity(v[2])};
}

std::set<Identity> IdentityTracker::live_identities() const {
    std::set<Identity> s;
    for (rgb::VertexId v : mesh_.vertices()) s.insert(identity(v));
    return s;
}

rgb::VertexId IdentityTracker::vertex_of(Identity id) const {
    for (rgb::VertexId v : mesh_.vertices())
        if (identity(v) == id) return v;
    return rgb::VertexId();
}

void IdentityTracker::vertex_added(const rgb::Mesh& mesh, rgb::VertexId v, rgb::VertexId a, rgb::VertexId b) {
    if (v.idx >= identity_.size()) identity_.resize(v.idx + 1, kNone);
    identity_[v.idx] = kNone;
    if (!mesh.is_live(a) || !mesh.is_live(b)) {
        ADD_FAILURE() << "vertex_added(" << v.idx << ") reports a dead endpoint " << a.idx << " or " << b.idx;
        return;
    }
    const std::optional<Identity> id = oracle_.midpoint(identity(a), identity(b));
    if (!id) {
        ADD_FAILURE() << "vertex " << v.idx << " inserted on " << a.idx << "-" << b.idx
                      << ", which is no edge of the oracle's uniform meshes (identities " << identity(a) << ", "
                      << identity(b) << ")";
        return;
    }
    EXPECT_EQ(oracle_.level(*id), mesh.level(v)) << "level of vertex " << v.idx << " inserted on " << a.idx << "-" << b.idx;
    identity_[v.idx] = *id;
}

void IdentityTracker::vertex_removed(const rgb::Mesh&, rgb::VertexId v) {
    if (v.idx < identity_.size()) identity_[v.idx] = kNone;
}

ChangeRecorder::ChangeRecorder(rgb::Mesh& mesh) : mesh_(mesh) { mesh_.add_observer(this); }
ChangeRecorder::~ChangeRecorder() { mesh_.remove_observer(this); }

void ChangeRecorder::clear() {
    vertices_added.clear();
    vertices_removed.clear();
    faces_added.clear();
    faces_removed.clear();
}

}  // namespace rgbtest
