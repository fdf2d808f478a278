// The value a budget orders splits by on a cage with detail (detail_error_value, rgb/lod/limit_error.h):
// an edge takes the departure from the dense surface beside it, where only its own split brings the
// surface closer, not the departure anywhere in its triangles. Worked out by hand on one flat triangle.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/limit_error.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/surface_point.h"

namespace rgbtest {
namespace {

// The triangle (0,0,0), (1,0,0), (0,1,0) with detail to level 2 on it, each point its own base-space
// point, but for the midpoint of the edge from corner 1 to corner 2, lifted by h along z.
TEST(DetailBudgetValue, AnEdgeTakesTheDepartureBesideItOnly) {
    const double h = 0.25;
    const std::vector<glm::dvec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<rgb::Triangle> triangles{{0, 1, 2}};
    const rgb::BaseMesh flat(positions, triangles);
    std::vector<glm::dvec3> values;
    for (const rgb::SurfacePoint& p : rgb::DetailPositions::grid_points(flat, 2)) {
        glm::dvec3 at = rgb::base_space_position(flat, p);
        if (at == glm::dvec3(0.5, 0.5, 0.0)) at.z = h;
        values.push_back(at);
    }
    auto detail = std::make_shared<const rgb::DetailPositions>(flat, 2, values);
    const auto base = std::make_shared<const rgb::BaseMesh>(positions, triangles, rgb::SharpFeatures{}, std::move(detail));
    const rgb::EdgeValue value = rgb::detail_error_value(base);
    const rgb::SurfacePoint c0 = rgb::corner_point(0, 0), c1 = rgb::corner_point(0, 1), c2 = rgb::corner_point(0, 2);
    // The flat face misses the lifted midpoint by h: a sample of the edge (1, 2).
    EXPECT_EQ(value(c1, c2), h);
    // Beside (0, 1), with the other two edges split, the pieces (1, M12, M20) and (1, M20, 0) show the
    // midpoint M12 where it is; the samples between it and corner 1 or M20 (weights (0, 3, 1) and
    // (1, 1, 2) over 4) lie halfway along the lifted node's side, h / 2 above the flat dense surface.
    // With all the triangle's samples, as the tolerance takes them, each edge took h.
    EXPECT_EQ(value(c0, c1), h / 2);
    EXPECT_EQ(value(c2, c0), h / 2);
    EXPECT_EQ(rgb::limit_error_value(base, 1.0)(c0, c1), h);
}

}  // namespace
}  // namespace rgbtest
