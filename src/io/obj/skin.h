#pragma once
// A glTF skin carried from the file read to the glTF files written, so that a character's levels of
// detail stay skinned: the skeleton (its joint nodes with their ancestors, as the file places them,
// and the inverse bind matrices) and, per vertex, its joints' weights. The weights are vertex data:
// they ride through subdivision as a vertex channel (io/skin_weights.h), as colours do. Only glTF
// carries a skin; the other formats leave it out.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace rgbio {

// A node of the skeleton with its local transform as the file wrote it (a matrix, or any of
// translation, rotation and scale; empty where the file has none).
struct SkeletonNode {
    std::string name;
    std::vector<double> matrix, translation, rotation, scale;
    std::vector<std::uint32_t> children;  // indices into Skeleton::nodes
};

struct Skeleton {
    std::vector<SkeletonNode> nodes;                  // in the file's node order
    std::vector<std::uint32_t> joints;                // per joint: its node
    std::vector<glm::dmat4> inverse_bind_matrices;    // per joint
    std::int64_t root = -1;                           // the skin's `skeleton` node, or -1
    std::string name;
};

// glTF's limit: a vertex is written with at most four joints (JOINTS_0/WEIGHTS_0).
inline constexpr std::size_t kMaxInfluences = 4;

// A vertex's joints and their weights, heaviest first; unused entries have weight 0 (and joint 0).
// Weights sum to 1.
struct JointInfluences {
    std::array<std::uint32_t, kMaxInfluences> joints{};
    std::array<double, kMaxInfluences> weights{};
    friend bool operator==(const JointInfluences&, const JointInfluences&) = default;
};

}  // namespace rgbio
