#include "uv_meshes.h"

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <random>

#include "support/test_meshes.h"
#include "test_mesh_input.h"

namespace osdoracle {
namespace {

constexpr int nx = 4, ny = 3;  // the grid of every grid case

// Grid coordinates of a vertex of rgbtest::grid(nx, ny), and of a triangle's centroid (times 3).
int grid_x(int v) { return v % (nx + 1); }
int grid_y(int v) { return v / (nx + 1); }
int centroid_x3(const std::array<int, 3>& t) { return grid_x(t[0]) + grid_x(t[1]) + grid_x(t[2]); }
int centroid_y3(const std::array<int, 3>& t) { return grid_y(t[0]) + grid_y(t[1]) + grid_y(t[2]); }

// Cuts the mesh into UV islands: island(t) for each triangle; a vertex gets one UV value per island
// around it, except where `joined(vertex)` says its corners share one value whatever their island.
// The UVs follow the positions, shifted per island and jittered per value (so no rule can pass by
// reproducing a linear function).
UvChannel islands(const FarInput& in, const std::function<int(int)>& island, const std::function<bool(int)>& joined) {
    UvChannel uv;
    std::map<std::pair<int, int>, int> value_of;
    std::mt19937 rng(4242);
    for (std::size_t t = 0; t < in.triangles.size(); ++t) {
        std::array<int, 3> corners{};
        for (int c = 0; c < 3; ++c) {
            const int v = in.triangles[t][c];
            const int i = joined(v) ? 0 : island(static_cast<int>(t));
            const auto [it, added] = value_of.emplace(std::pair{v, i}, static_cast<int>(uv.values.size()));
            if (added) {
                const glm::dvec3& p = in.positions[v];
                const double jitter_u = 0.03 * (rng() / 4294967296.0 - 0.5), jitter_v = 0.03 * (rng() / 4294967296.0 - 0.5);
                uv.values.push_back({0.3 * p.x + 0.2 * p.z + 0.7 * i + jitter_u, 0.3 * p.y - 0.1 * p.z + 0.4 * i + jitter_v});
            }
            corners[c] = it->second;
        }
        uv.corners.push_back(corners);
    }
    return uv;
}

bool never(int) { return false; }

UvCase grid_case(const std::string& name, const std::function<int(const std::array<int, 3>&)>& island,
                 const std::function<bool(int)>& joined = never) {
    FarInput in = far_input(rgbtest::grid(nx, ny));
    in.uv = islands(in, [&](int t) { return island(in.triangles[t]); }, joined);
    return {name, in};
}

// Left and right of the column x = 2.
int halves(const std::array<int, 3>& t) { return centroid_x3(t) > 6 ? 1 : 0; }

void sharpen_row(FarInput& in, int y, double sharpness) {
    for (int x = 0; x < nx; ++x) in.creases.push_back({y * (nx + 1) + x, y * (nx + 1) + x + 1, sharpness});
}

}  // namespace

std::vector<UvCase> uv_cases() {
    std::vector<UvCase> cases;
    cases.push_back(grid_case("seam_across_grid", halves));
    // The seam stops at (2, 2): above y = 2 the two halves share their UVs, so (2, 2) is a UV dart.
    cases.push_back(grid_case("seam_ending_inside", halves, [](int v) { return grid_y(v) >= 2; }));
    // Three seams meet at (2, 1) (three values there), four at the crossing of row 1 and column 2.
    cases.push_back(grid_case("three_seams_meeting", [](const std::array<int, 3>& t) {
        return centroid_x3(t) > 6 ? 2 : (centroid_y3(t) < 3 ? 0 : 1);
    }));
    cases.push_back(grid_case("four_seams_meeting", [](const std::array<int, 3>& t) {
        return halves(t) + (centroid_y3(t) < 3 ? 0 : 2);
    }));
    // One interior triangle is its own island: its three corners have a one-face span.
    UvCase island = grid_case("one_triangle_island", [](const std::array<int, 3>& t) {
        return centroid_x3(t) == 5 && centroid_y3(t) == 4 ? 1 : 0;  // the triangle (1,1), (2,1), (2,2)
    });
    cases.push_back(island);
    // A boundary triangle as its own island: both ends of its boundary edge lie on seams.
    cases.push_back(grid_case("boundary_triangle_island", [](const std::array<int, 3>& t) {
        return centroid_x3(t) == 8 && centroid_y3(t) == 1 ? 1 : 0;  // the triangle (2,0), (3,0), (3,1)
    }));

    UvCase corner_boundary = grid_case("seam_across_grid_edge_and_corner", halves);
    corner_boundary.input.boundary = BoundaryInterpolation::edge_and_corner;
    cases.push_back(corner_boundary);

    // Row 1 infinitely sharp or of sharpness 2: at (2, 1) each UV span contains a sharp edge.
    UvCase sharp_row = grid_case("seam_crossing_sharp_row", halves);
    sharpen_row(sharp_row.input, 1, infinite_sharpness);
    cases.push_back(sharp_row);
    UvCase semi_row = grid_case("seam_crossing_semi_sharp_row", halves);
    sharpen_row(semi_row.input, 1, 2.0);
    cases.push_back(semi_row);

    // Only the left half of row 1 of sharpness 2: at (2, 1) one UV span holds a semi-sharp edge and
    // the other does not, which the "plus" options treat as a dependency between the two values.
    UvCase half_row = grid_case("seam_beside_semi_sharp_edge", halves);
    half_row.input.creases = {{5, 6, 2.0}, {6, 7, 2.0}};  // (0, 1) - (1, 1) - (2, 1)
    cases.push_back(half_row);

    // A semi-sharp corner tag on the seam, at (2, 1): both of its values stay put for two levels, then
    // move along the seam.
    UvCase semi_corner = grid_case("seam_through_semi_sharp_corner", halves);
    semi_corner.input.corners = {{7, 2.0}};
    cases.push_back(semi_corner);

    // A closed bipyramid cut along its equator into two UV caps; then the same with the equator sharp.
    FarInput caps = far_input(rgbtest::bipyramid(6));
    caps.uv = islands(caps, [&](int t) {
        const auto& tri = caps.triangles[t];
        return tri[0] == 6 || tri[1] == 6 || tri[2] == 6 ? 0 : 1;  // vertex 6 is the upper apex
    }, never);
    cases.push_back({"equator_seam", caps});
    for (int i = 0; i < 6; ++i) caps.creases.push_back({i, (i + 1) % 6, infinite_sharpness});
    cases.push_back({"equator_seam_on_crease", caps});
    return cases;
}

std::vector<UvCase> uv_bow_tie_cases() {
    std::vector<UvCase> cases;
    // UV bow-ties: one UV value used by two separate groups of triangles around a vertex. Around grid
    // (2, 1) the triangles, counter-clockwise from the lower right, have centroids (times 3) (7, 2),
    // (8, 4), (7, 5), (5, 4), (4, 2), (5, 1). Two one-triangle islands there, (8, 4) and (5, 4), leave
    // the surrounding value with the spans {(7, 5)} and {(4, 2), (5, 1), (7, 2)}.
    cases.push_back(grid_case("bow_tie_between_two_islands", [](const std::array<int, 3>& t) {
        const int x = centroid_x3(t), y = centroid_y3(t);
        return x == 8 && y == 4 ? 1 : (x == 5 && y == 4 ? 2 : 0);
    }));
    // A checkerboard of two values cut at column 2 and row 1: both values at (2, 1) have two spans.
    // Far gives the value of its first face there one sibling (a corner) and each span of the other
    // value a sibling of its own (under none a crease each): treating both values as corners misses
    // Far's UVs by 0.059 at level 1.
    UvCase checkerboard = grid_case("bow_tie_checkerboard", [](const std::array<int, 3>& t) {
        return (centroid_x3(t) > 6) != (centroid_y3(t) > 3) ? 1 : 0;
    });
    cases.push_back(checkerboard);
    // The same with row 1 of sharpness 2: the bow-tie values' spans hold semi-sharp edges.
    sharpen_row(checkerboard.input, 1, 2.0);
    checkerboard.name = "bow_tie_checkerboard_semi_sharp_row";
    cases.push_back(checkerboard);
    // On the boundary at (2, 0): the middle one of its three triangles, (7, 2), is an island touching
    // the boundary at that vertex only, so the outer two share a value across it.
    cases.push_back(grid_case("bow_tie_on_boundary", [](const std::array<int, 3>& t) {
        return centroid_x3(t) == 7 && centroid_y3(t) == 2 ? 1 : 0;
    }));
    // A half disc of four triangles around a boundary vertex with alternating values A B A B: Far
    // walks from one end of the boundary, so which value is split tells whether the walk starts at
    // the same end as the core's.
    FarInput fan;
    fan.positions.push_back({0.0, 0.0, 0.1});
    for (int k = 0; k <= 4; ++k) {
        const double angle = 0.25 * std::numbers::pi * k;
        fan.positions.push_back({std::cos(angle), std::sin(angle) * (1.0 + 0.1 * k), 0.05 * k});
    }
    for (int k = 0; k < 4; ++k) fan.triangles.push_back({0, k + 1, k + 2});
    fan.uv = islands(fan, [](int t) { return t % 2; }, never);
    cases.push_back({"bow_ties_alternating_on_boundary", fan});
    return cases;
}

}  // namespace osdoracle
