#include "support/octahedron_edge.h"

#include "support/checked_operators.h"

namespace rgbtest {

std::pair<rgb::VertexId, rgb::VertexId> OctahedronEdge::make_both_sides_red(bool same) {
    const rgb::VertexId m1 = split_checked(mesh, b, x, rgb::SplitKind::GG);
    const rgb::VertexId m2 = same ? split_checked(mesh, y, b, rgb::SplitKind::GG) : split_checked(mesh, a, y, rgb::SplitKind::GG);
    return {m1, m2};
}

}  // namespace rgbtest
