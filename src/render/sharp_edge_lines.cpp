#include "render/sharp_edge_lines.h"

#include <algorithm>

#include "render/surface_geometry.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/vertex_rules.h"

namespace render {

void SharpEdgeLines::rebuild(const rgb::Mesh& mesh) {
    sides_.clear();
    slots_with_sides_ = 0;
    if (mesh.base().sharp_features().edges.empty()) return;
    for (rgb::FaceId f : mesh.faces()) look_at(mesh, f);
}

void SharpEdgeLines::update(const rgb::Mesh& mesh, std::span<const SlotRange> changed) {
    if (mesh.base().sharp_features().edges.empty()) {
        rebuild(mesh);
        return;
    }
    for (const SlotRange& range : changed)
        for (std::uint32_t slot = range.first; slot < range.first + range.count; ++slot) look_at(mesh, rgb::FaceId(slot));
}

void SharpEdgeLines::look_at(const rgb::Mesh& mesh, rgb::FaceId f) {
    std::uint8_t sides = 0;
    if (mesh.is_live(f)) {
        const rgb::BaseMesh& base = mesh.base();
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
            const rgb::VertexId from = mesh.from_vertex(h), to = mesh.to_vertex(h);
            // Boundary edges are sharp without a tag, and not drawn (as rgb::sharp_mesh_edges).
            if (mesh.is_boundary(h) || to.idx < from.idx) continue;
            // Semi-sharp edges are drawn too: their tag shapes the surface even where it has run out.
            const auto on = rgb::base_edge_between(base, mesh.address(from), mesh.address(to));
            if (on && base.edge_sharpness(*on) != 0) sides |= static_cast<std::uint8_t>(1u << i);
        }
    }
    if (f.idx >= sides_.size()) {
        if (sides == 0) return;
        sides_.resize(f.idx + 1, 0);
    }
    slots_with_sides_ -= sides_[f.idx] != 0;
    slots_with_sides_ += sides != 0;
    sides_[f.idx] = sides;
}

std::vector<glm::vec3> SharpEdgeLines::lines(const SurfaceGeometry& geometry) const {
    std::vector<glm::vec3> lines;
    if (slots_with_sides_ == 0) return lines;
    const std::size_t slots = std::min(sides_.size(), geometry.face_slots());
    const auto corners = geometry.vertices();
    for (std::size_t slot = 0; slot < slots; ++slot) {
        if (sides_[slot] == 0) continue;
        for (std::size_t i = 0; i < 3; ++i)
            if ((sides_[slot] >> i) & 1u) {
                lines.push_back(corners[3 * slot + i].position);
                lines.push_back(corners[3 * slot + (i + 1) % 3].position);
            }
    }
    return lines;
}

}  // namespace render
