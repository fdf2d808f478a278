#pragma once
// A Mesh rebuilt from its state (mesh/state.h) with its values: the topology comes from the
// addresses, every insertion position and the limits the display needs from the base mesh by the
// hierarchy evaluator (spec §4.2), so a restored mesh has the same vertices, faces and positions, bit
// for bit, as the one the operators made. Retagging a mesh (other crease tags) recomputes its values
// the same way.
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/state.h"
#include "rgb/rules/sharp_features.h"
#include "rgb/support/progress.h"
#include "rgb/values/vertex_channel.h"

namespace rgb {

// A vertex channel (vertex_channel.h) restored with a mesh: the positions' pass gives its values
// too, at the cost of its arithmetic (the neighbours are looked up once).
struct RestoredChannel {
    std::span<const glm::dvec3> base_values;  // one per base vertex
    ChannelLevel level = ChannelLevel::Displayed;
    std::vector<glm::dvec3> values;  // set by restore_state: one per vertex of the state, as vertex_channel_values gives them
};

// The positions of a restored mesh's vertices, displayed or limit ones (what a saved file's v lines
// hold, which the loader checks), from restore_state's positions pass: asked of the restored mesh
// vertex by vertex, each would look up its display level and its cached limit again.
struct RestoredPositions {
    ChannelLevel level = ChannelLevel::Displayed;
    std::vector<glm::dvec3> values;  // set by restore_state: one per vertex of the state, as displayed_position or limit_position gives them
};

// Throws std::invalid_argument with a readable reason if the state is not a valid RGB triangulation
// of its base mesh in the normal form the core keeps (io turns that into a file error); the first
// problem in the order vertices, faces, types, positions, invariants is the one named. Linear in the
// size of the state, its passes over all vertices or faces on all cores (parallel.h). The restored
// mesh has the limits cached that its displayed positions need. `progress` hears of each pass done.
// A non-null `channel` gets its values from the pass that computes the positions; it must have one
// value per base vertex, or std::invalid_argument is thrown. A non-null `positions` gets its values
// from that pass too.
Mesh restore_state(const MeshState& state, const ProgressSpan& progress = {}, RestoredChannel* channel = nullptr,
                   RestoredPositions* positions = nullptr);

// Gives the mesh's base mesh other crease and corner tags (the editor's crease tool, the CLI's
// --sharp-angle): the vertex set, the faces and every slot stay, every value follows the new rules
// (so an undo journal's records stay valid and an undo is another retag). Observers are not told:
// every position changes. Throws std::invalid_argument for tags BaseMesh refuses, before any change.
void set_sharp_features(Mesh& mesh, const SharpFeatures& features);
// The same on a copy.
Mesh with_sharp_features(const Mesh& mesh, const SharpFeatures& features);

}  // namespace rgb
