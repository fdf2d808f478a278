#include "io/formats/gltf_skin.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "io/obj/obj_error.h"

namespace rgbio {

std::vector<JointInfluences> joint_influences(std::span<const double> joints, std::span<const double> weights, std::size_t joint_count,
                                              const std::string& path, std::size_t& unweighted) {
    const std::size_t n = std::min(joints.size(), weights.size()) / kMaxInfluences;
    std::vector<JointInfluences> out(n);
    for (std::size_t v = 0; v < n; ++v) {
        JointInfluences& in = out[v];
        std::size_t used = 0;
        double sum = 0.0;
        for (std::size_t k = 0; k < kMaxInfluences; ++k) {
            const double w = weights[kMaxInfluences * v + k];
            const double joint = joints[kMaxInfluences * v + k];
            if (!std::isfinite(w) || w < 0.0)
                throw ObjError(ObjProblem::Malformed, path, 0, "vertex " + std::to_string(v + 1) + " of a skinned primitive has the weight " + std::to_string(w));
            if (w == 0.0) continue;
            if (joint >= static_cast<double>(joint_count))
                throw ObjError(ObjProblem::Malformed, path, 0,
                               "vertex " + std::to_string(v + 1) + " of a skinned primitive names joint " + std::to_string(static_cast<std::size_t>(joint)) +
                                   " of a skin with " + std::to_string(joint_count));
            const auto j = static_cast<std::uint32_t>(joint);
            sum += w;
            const auto same = std::find(in.joints.begin(), in.joints.begin() + used, j);
            if (same != in.joints.begin() + used) {
                in.weights[static_cast<std::size_t>(same - in.joints.begin())] += w;
            } else {
                in.joints[used] = j;
                in.weights[used++] = w;
            }
        }
        if (!(sum > 0.0)) {
            ++unweighted;
            continue;
        }
        // Heaviest first, by insertion (four entries).
        for (std::size_t k = 1; k < used; ++k)
            for (std::size_t i = k; i > 0 && (in.weights[i] > in.weights[i - 1] || (in.weights[i] == in.weights[i - 1] && in.joints[i] < in.joints[i - 1])); --i) {
                std::swap(in.weights[i], in.weights[i - 1]);
                std::swap(in.joints[i], in.joints[i - 1]);
            }
        for (std::size_t k = 0; k < used; ++k) in.weights[k] /= sum;
    }
    return out;
}

Skeleton read_skeleton(const tinygltf::Model& model, int skin_index, std::span<const double> inverse_bind_matrices, const glm::dmat4& mesh_transform) {
    const tinygltf::Skin& skin = model.skins[static_cast<std::size_t>(skin_index)];
    const std::size_t nodes = model.nodes.size();
    std::vector<std::int64_t> parent(nodes, -1);
    for (std::size_t n = 0; n < nodes; ++n)
        for (int child : model.nodes[n].children)
            if (child >= 0 && static_cast<std::size_t>(child) < nodes) parent[static_cast<std::size_t>(child)] = static_cast<std::int64_t>(n);
    // The joints, the skeleton root and every ancestor of them: the joints' world transforms come
    // from the whole chain above them.
    std::vector<std::uint8_t> kept(nodes, 0);
    const auto keep = [&](int node) {
        for (std::int64_t n = node; n >= 0 && static_cast<std::size_t>(n) < nodes && !kept[static_cast<std::size_t>(n)]; n = parent[static_cast<std::size_t>(n)])
            kept[static_cast<std::size_t>(n)] = 1;
    };
    for (int joint : skin.joints) keep(joint);
    keep(skin.skeleton);
    std::vector<std::uint32_t> index(nodes, UINT32_MAX);
    Skeleton out;
    out.name = skin.name;
    for (std::size_t n = 0; n < nodes; ++n)
        if (kept[n]) {
            index[n] = static_cast<std::uint32_t>(out.nodes.size());
            const tinygltf::Node& node = model.nodes[n];
            out.nodes.push_back({node.name, node.matrix, node.translation, node.rotation, node.scale, {}});
        }
    for (std::size_t n = 0; n < nodes; ++n)
        if (kept[n] && parent[n] >= 0) out.nodes[index[static_cast<std::size_t>(parent[n])]].children.push_back(index[n]);
    for (int joint : skin.joints) out.joints.push_back(index[static_cast<std::size_t>(joint)]);
    if (skin.skeleton >= 0) out.root = index[static_cast<std::size_t>(skin.skeleton)];
    const bool moved = mesh_transform != glm::dmat4(1.0);
    const glm::dmat4 undo = moved ? glm::inverse(mesh_transform) : glm::dmat4(1.0);
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const glm::dmat4 m = inverse_bind_matrices.size() >= 16 * (j + 1) ? glm::make_mat4(inverse_bind_matrices.data() + 16 * j) : glm::dmat4(1.0);
        out.inverse_bind_matrices.push_back(moved ? m * undo : m);
    }
    return out;
}

}  // namespace rgbio
