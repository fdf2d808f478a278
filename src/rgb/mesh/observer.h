#pragma once
// The one narrow interface through which every operator reports what it changed. The renderer uses it
// to re-upload only dirty ranges; the editor uses it to record undo; tests use it to track vertex
// identity for the uniform Loop oracle.
//
// Order within one Mesh::replace_faces: face_removed for each deleted face (the face is still
// readable), then vertex_removed (still readable), then vertex_added, then face_added for each new
// face (already readable). A split is one such block (the swaps it implies are folded in); a removal
// may swap before or after its merge, each swap a block of its own. The displayed position of a vertex changes only when a face
// incident to it is added, so consumers refresh the vertices of added faces.
#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

class MeshObserver {
public:
    virtual ~MeshObserver() = default;
    // v was inserted on the edge (a, b) of the next coarser uniform level.
    virtual void vertex_added(const Mesh&, VertexId /*v*/, VertexId /*a*/, VertexId /*b*/) {}
    virtual void vertex_removed(const Mesh&, VertexId /*v*/) {}
    virtual void face_added(const Mesh&, FaceId) {}
    virtual void face_removed(const Mesh&, FaceId) {}
    // The mesh is about to move its face or vertex arrays or its table of limits into larger ones (an
    // operation past the room reserved), or to be assigned to or moved from: memory handed out for
    // them (Mesh::room_ahead, limit_table) may be freed after. Outside the order above: it comes
    // before anything of the operation that needs the room has changed.
    virtual void arrays_moving(const Mesh&) {}
};

}  // namespace rgb
