#include "io/obj/labelled_faces.h"

#include <array>
#include <map>

#include "rgb/mesh/face_location.h"

namespace rgbio {

namespace {

// material, group, object, smoothing group
using LabelKey = std::array<std::uint32_t, 4>;

LabelKey key_of(const BaseFaceLabels& labels, std::uint32_t base_face) {
    auto index = [&](const FaceLabels& l) { return l.empty() ? kNoIndex : l.of_triangle[base_face]; };
    return {index(labels.materials), index(labels.groups), index(labels.objects),
            labels.smoothing_groups.empty() ? 0u : labels.smoothing_groups[base_face]};
}

// The lines that switch from `before` to `key` (everything that is set, for the first block). A
// label going back to none is a bare keyword, which OBJ readers take as "none" (rgbsub's does).
std::string label_lines(const BaseFaceLabels& labels, const LabelKey* before, const LabelKey& key) {
    std::string lines;
    auto label = [&](const char* keyword, const FaceLabels& table, int k) {
        if (before ? (*before)[k] == key[k] : key[k] == kNoIndex) return;
        lines += keyword;
        if (key[k] != kNoIndex) lines += ' ' + table.names[key[k]];
        lines += '\n';
    };
    label("o", labels.objects, 2);
    label("g", labels.groups, 1);
    label("usemtl", labels.materials, 0);
    if (before ? (*before)[3] != key[3] : key[3] != 0) lines += key[3] == 0 ? "s off\n" : "s " + std::to_string(key[3]) + "\n";
    return lines;
}

}  // namespace

LabelledFaceOrder labelled_face_order(const rgb::Mesh& mesh, const BaseFaceLabels& labels) {
    LabelledFaceOrder order;
    order.faces.reserve(mesh.num_faces());
    if (labels.empty()) {
        for (rgb::FaceId f : mesh.faces()) order.faces.push_back(f);
        return order;
    }
    // Blocks in order of first appearance on the base faces.
    const std::size_t base_faces = mesh.base().num_faces();
    std::map<LabelKey, std::uint32_t> block_of_key;
    std::vector<LabelKey> keys;
    std::vector<std::uint32_t> block_of_base(base_faces);
    for (std::uint32_t b = 0; b < base_faces; ++b) {
        const LabelKey key = key_of(labels, b);
        const auto [it, inserted] = block_of_key.try_emplace(key, static_cast<std::uint32_t>(keys.size()));
        if (inserted) keys.push_back(key);
        block_of_base[b] = it->second;
    }
    // A counting sort by block keeps slot order within each block.
    std::vector<std::uint32_t> block_of_face;
    block_of_face.reserve(mesh.num_faces());
    std::vector<std::size_t> start(keys.size() + 1, 0);
    for (rgb::FaceId f : mesh.faces()) {
        block_of_face.push_back(block_of_base[rgb::base_face_of(mesh, f)]);
        ++start[block_of_face.back() + 1];
    }
    for (std::size_t k = 0; k < keys.size(); ++k) start[k + 1] += start[k];
    order.faces.resize(mesh.num_faces());
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    std::size_t i = 0;
    for (rgb::FaceId f : mesh.faces()) order.faces[next[block_of_face[i++]]++] = f;
    const LabelKey* before = nullptr;
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (start[k] == start[k + 1]) continue;  // cannot happen: every base face holds a face
        order.blocks.push_back({start[k], label_lines(labels, before, keys[k])});
        before = &keys[k];
    }
    return order;
}

}  // namespace rgbio
