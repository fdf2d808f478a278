#pragma once
// Collects what the core changed between two renderer updates, through the core's observer
// interface. Registers itself with the mesh for its lifetime. It never fails while told of a change
// (a failure would reach the core's operators): when memory runs out it forgets the details and
// reports that everything may have changed.
#include <vector>

#include "rgb/mesh/handles.h"
#include "rgb/mesh/observer.h"

namespace rgb {
class Mesh;
}

namespace render {

class MeshChanges : public rgb::MeshObserver {
public:
    explicit MeshChanges(rgb::Mesh& mesh);
    ~MeshChanges() override;
    MeshChanges(const MeshChanges&) = delete;
    MeshChanges& operator=(const MeshChanges&) = delete;

    void face_added(const rgb::Mesh& mesh, rgb::FaceId f) override;
    void face_removed(const rgb::Mesh& mesh, rgb::FaceId f) override;

    // Face slots that were created or freed (possibly both, when a slot is reused), unsorted.
    const std::vector<rgb::FaceId>& changed_faces() const { return changed_faces_; }
    // Vertices whose displayed position may have changed: the corners of added faces (observer.h).
    const std::vector<rgb::VertexId>& moved_vertices() const { return moved_vertices_; }
    bool empty() const { return changed_faces_.empty() && !everything_; }
    // Set when the lists above could not be kept: consumers rebuild everything.
    bool everything() const { return everything_; }
    void clear();

private:
    void give_up();

    rgb::Mesh* mesh_;
    bool everything_ = false;
    std::vector<rgb::FaceId> changed_faces_;
    std::vector<rgb::VertexId> moved_vertices_;
};

}  // namespace render
