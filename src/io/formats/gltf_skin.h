#pragma once
// A glTF skin read for io/obj/skin.h: each vertex's JOINTS_0/WEIGHTS_0 made into its influences,
// and the skin's skeleton carried out of the file's node tree.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "io/obj/skin.h"

namespace tinygltf {
class Model;
}

namespace rgbio {

// Per vertex, its four joints and weights (`joints` and `weights` as read, four values a vertex)
// as influences: zero weights left out, a joint named twice counted once with the sum, heaviest
// first (ties: lower joint first), renormalised to sum 1. A vertex whose weights are all zero gets
// none (all weights 0) and is counted in `unweighted`. Throws ObjError (Malformed, for `path`) for
// a negative or non-finite weight, or a weighted joint beyond the skin's `joint_count`.
std::vector<JointInfluences> joint_influences(std::span<const double> joints, std::span<const double> weights, std::size_t joint_count,
                                              const std::string& path, std::size_t& unweighted);

// The skeleton of model.skins[skin]: its joints' nodes, their ancestors and the skin's `skeleton`
// node, with their transforms and names, in the file's node order. `inverse_bind_matrices`: 16
// values per joint as read (column-major), or empty for the spec's identities. The mesh's positions
// were moved by `mesh_transform` (its node's transform), which glTF's skinning ignores: the inverse
// bind matrices take its inverse, so that the skinned pose stays the file's (unchanged where it is
// the identity).
Skeleton read_skeleton(const tinygltf::Model& model, int skin, std::span<const double> inverse_bind_matrices, const glm::dmat4& mesh_transform);

}  // namespace rgbio
