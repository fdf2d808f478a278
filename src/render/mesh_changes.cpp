#include "render/mesh_changes.h"

#include <new>

#include "rgb/mesh/mesh.h"

namespace render {

MeshChanges::MeshChanges(rgb::Mesh& mesh) : mesh_(&mesh) { mesh_->add_observer(this); }

MeshChanges::~MeshChanges() { mesh_->remove_observer(this); }

void MeshChanges::face_added(const rgb::Mesh& mesh, rgb::FaceId f) {
    if (everything_) return;
    try {
        changed_faces_.push_back(f);
        for (rgb::VertexId v : mesh.face_vertices(f)) moved_vertices_.push_back(v);
    } catch (const std::bad_alloc&) {
        give_up();
    }
}

void MeshChanges::face_removed(const rgb::Mesh&, rgb::FaceId f) {
    if (everything_) return;
    try {
        changed_faces_.push_back(f);
    } catch (const std::bad_alloc&) {
        give_up();
    }
}

void MeshChanges::give_up() {
    everything_ = true;
    changed_faces_ = {};
    moved_vertices_ = {};
}

void MeshChanges::clear() {
    changed_faces_.clear();
    moved_vertices_.clear();
    everything_ = false;
}

}  // namespace render
