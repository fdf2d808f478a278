#include "render/mesh_changes.h"

#include "rgb/mesh.h"

namespace render {

MeshChanges::MeshChanges(rgb::Mesh& mesh) : mesh_(&mesh) { mesh_->add_observer(this); }

MeshChanges::~MeshChanges() { mesh_->remove_observer(this); }

void MeshChanges::face_added(const rgb::Mesh& mesh, rgb::FaceId f) {
    changed_faces_.push_back(f);
    for (rgb::VertexId v : mesh.face_vertices(f)) moved_vertices_.push_back(v);
}

void MeshChanges::face_removed(const rgb::Mesh&, rgb::FaceId f) { changed_faces_.push_back(f); }

void MeshChanges::clear() {
    changed_faces_.clear();
    moved_vertices_.clear();
}

}  // namespace render
