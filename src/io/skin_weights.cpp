#include "io/skin_weights.h"

#include <algorithm>
#include <set>

namespace rgbio {

namespace {

// Puts (joint, weight) among the heaviest four, kept in order (joints come in increasing order, so
// an equal weight goes after the earlier joint's).
void keep_heaviest(JointInfluences& in, std::uint32_t joint, double weight) {
    if (!(weight > 0.0)) return;
    std::size_t k = 0;
    while (k < kMaxInfluences && in.weights[k] >= weight) ++k;
    if (k == kMaxInfluences) return;
    for (std::size_t i = kMaxInfluences - 1; i > k; --i) {
        in.weights[i] = in.weights[i - 1];
        in.joints[i] = in.joints[i - 1];
    }
    in.weights[k] = weight;
    in.joints[k] = joint;
}

}  // namespace

std::vector<JointInfluences> vertex_influences(const rgb::Mesh& mesh, std::span<const JointInfluences> base, rgb::ChannelLevel level) {
    std::set<std::uint32_t> used;
    for (const JointInfluences& in : base)
        for (std::size_t k = 0; k < kMaxInfluences; ++k)
            if (in.weights[k] > 0.0) used.insert(in.joints[k]);
    const std::vector<std::uint32_t> joints(used.begin(), used.end());
    std::vector<JointInfluences> out(mesh.vertex_capacity());
    // Three joints a pass: a channel holds three values per vertex.
    std::vector<glm::dvec3> values(base.size());
    for (std::size_t first = 0; first < joints.size(); first += 3) {
        const std::size_t count = std::min<std::size_t>(3, joints.size() - first);
        for (std::size_t v = 0; v < base.size(); ++v) {
            values[v] = glm::dvec3(0.0);
            for (std::size_t k = 0; k < kMaxInfluences; ++k)
                for (std::size_t c = 0; c < count; ++c)
                    if (base[v].weights[k] > 0.0 && base[v].joints[k] == joints[first + c]) values[v][static_cast<int>(c)] += base[v].weights[k];
        }
        const std::vector<glm::dvec3> weights = rgb::vertex_channel_values(mesh, values, level);
        for (rgb::VertexId v : mesh.vertices())
            for (std::size_t c = 0; c < count; ++c) keep_heaviest(out[v.idx], joints[first + c], weights[v.idx][static_cast<int>(c)]);
    }
    for (rgb::VertexId v : mesh.vertices()) {
        JointInfluences& in = out[v.idx];
        double sum = 0.0;
        for (double w : in.weights) sum += w;
        if (sum > 0.0)
            for (double& w : in.weights) w /= sum;
    }
    return out;
}

}  // namespace rgbio
