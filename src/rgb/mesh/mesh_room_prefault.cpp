#include "rgb/mesh/mesh_room_prefault.h"

namespace rgb {

MeshRoomPrefault::MeshRoomPrefault(Mesh& mesh, std::size_t faces, std::size_t vertices) : mesh_(mesh) {
    mesh_.add_observer(this);
    prefault_.emplace(mesh_.room_ahead(faces, vertices));
}

MeshRoomPrefault::~MeshRoomPrefault() {
    prefault_.reset();  // before the mesh can move anything it read
    mesh_.remove_observer(this);
}

}  // namespace rgb
