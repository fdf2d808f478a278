#pragma once
// The adaptive state of a Mesh as plain data, for persistence (io) and tests, and its topology
// rebuilt from it (values/restore_state.h adds the positions): the base mesh with its
// crease and corner tags, each live vertex's address in the hierarchy and the live faces. Nothing else
// is needed: a face's colour, level and red edge follow from its corners' addresses (spec §1.3), every
// Loop value from the base mesh (loop_geometry.h), so a restored mesh has the same vertices, faces and
// positions bit for bit.
// Slots are compacted: vertex i of the state is the i-th live vertex slot, base vertices first.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/address_index.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/surface_point.h"
#include "rgb/support/progress.h"

namespace rgb {


struct MeshState {
    std::vector<glm::dvec3> base_positions;
    std::vector<Triangle> base_triangles;
    SharpFeatures sharp_features;  // the base mesh's tags (BaseMesh::sharp_features)
    std::vector<SurfacePoint> vertices;  // base vertices first, in base order
    std::vector<Triangle> faces;         // indices into vertices
    // A cage's detail positions (detail_positions.h), shared with the base mesh; null for a plain mesh.
    std::shared_ptr<const DetailPositions> detail;
};

MeshState capture_state(const Mesh& mesh);

// The passes of a restore (values/restore_state.h) as fractions of its time, for its progress
// (measured at 1M and 6M triangles; the passes are linear, so the shares hold at any size).
inline constexpr double kRestoreBaseBuilt = 0.01, kRestoreMatched = 0.26, kRestoreTyped = 0.40, kRestorePositioned = 0.88,
                        kRestoreChecked = 0.97;

// Throws std::invalid_argument("invalid RGB state: " + what): the one error of a restore.
[[noreturn]] void invalid_state(const std::string& what);
// The state's base mesh with its tags, or invalid_state naming what BaseMesh refused.
std::shared_ptr<const BaseMesh> restored_base_mesh(const MeshState& state);

// A state's topology rebuilt: the mesh with every vertex, face, colour and level (spec §1.3), each
// vertex's address made canonical, and the index of those addresses. The insertion positions are
// the base positions' placeholders until the caller assigns them (Mesh::assign_insertion_positions).
struct RestoredTopology {
    Mesh mesh;
    std::vector<SurfacePoint> points;  // canonical addresses, one per vertex of the state
    AddressIndex index;
};
// The topology of `state` over its base mesh, or invalid_state naming the first problem in the order
// vertices, faces, types; `progress` hears of each pass done (up to kRestoreTyped).
RestoredTopology restore_topology(const MeshState& state, std::shared_ptr<const BaseMesh> base, const ProgressSpan& progress);
// The invariants a restored mesh must keep, with its hierarchy places and the normal form; throws
// invalid_state naming the first one broken.
void check_restored(const Mesh& mesh, const ProgressSpan& progress);

}  // namespace rgb
