#pragma once
// A skin's joint weights over an adaptive mesh. Each joint's weight is vertex data: glTF skins
// blend linearly in the weights, and Loop's rules are linear, so every joint's weight rides through
// subdivision as a vertex channel (rgb/values/vertex_channel.h: the position stencils, OpenSubdiv's
// primvars), and the weights of a vertex still sum to 1 (the stencils are affine). A vertex of a
// refined mesh can take weight from more joints than its base vertices had; glTF writes four, so
// the four heaviest are kept and renormalised.
#include <span>
#include <vector>

#include "io/obj/skin.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/vertex_channel.h"

namespace rgbio {

// Per vertex slot of `mesh` (dead slots: no weight), its influences from `base` (one per base
// vertex): per joint, its channel's value at `level`; the four largest (ties: the lower joint) over
// their sum. Throws std::invalid_argument if base does not have one entry per base vertex.
std::vector<JointInfluences> vertex_influences(const rgb::Mesh& mesh, std::span<const JointInfluences> base, rgb::ChannelLevel level);

}  // namespace rgbio
