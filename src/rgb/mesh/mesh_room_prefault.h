#pragma once
// The mesh's room for a refinement (Mesh::room_ahead) faulted in and touched on another core
// (Prefault), for as long as the mesh keeps that room: it stops before the mesh moves its arrays (a
// refinement that outgrows its estimate), so its reads never reach memory that is gone.
#include <cstddef>
#include <optional>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"
#include "rgb/support/prefault.h"

namespace rgb {

class MeshRoomPrefault : public MeshObserver {
public:
    MeshRoomPrefault(Mesh& mesh, std::size_t faces, std::size_t vertices);
    ~MeshRoomPrefault() override;
    MeshRoomPrefault(const MeshRoomPrefault&) = delete;
    MeshRoomPrefault& operator=(const MeshRoomPrefault&) = delete;

    void arrays_moving(const Mesh&) override { prefault_.reset(); }

private:
    Mesh& mesh_;
    std::optional<Prefault> prefault_;
};

}  // namespace rgb
