#include "rgb/values/loop_split.h"

#include <algorithm>
#include <stdexcept>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

namespace {

// Whether the interior edge (a, b) lies on a base edge still sharp at its level, so that the vertex
// inserted on it is its midpoint (docs/loop-creases.md §3).
bool on_sharp_edge(const Mesh& mesh, VertexId a, VertexId b) {
    const BaseMesh& base = mesh.base();
    if (!base.has_sharp_features()) return false;
    const SurfacePoint pa = mesh.address(a), pb = mesh.address(b);
    const auto on = base_edge_between(base, pa, pb);
    return on && sharp_at_level(base.edge_sharpness(*on), std::max(pa.level, pb.level));
}

}  // namespace

glm::dvec3 split_position(const Mesh& mesh, HalfedgeId h) {
    const int l = mesh.edge_type(h).level;
    const auto s = split_stencil(mesh, h);
    const VertexId a = s[0], b = s[1];
    const glm::dvec3 pa = control_point(mesh, a, l), pb = control_point(mesh, b, l);
    if (s.size() == 2 || on_sharp_edge(mesh, a, b)) return boundary_edge_point(pa, pb);
    return interior_edge_point(pa, pb, control_point(mesh, s[2], l), control_point(mesh, s[3], l));
}

VertexId split_edge(Mesh& mesh, HalfedgeId h) {
    // Checked before the stencil is walked, which needs a splittable edge.
    if (!can_split_edge(mesh, h)) throw std::logic_error("split_edge: the edge is not splittable");
    return split_edge_at(mesh, h, split_position(mesh, h));
}

}  // namespace rgb
