#include "crease_meshes.h"

#include <algorithm>
#include <set>

#include "support/test_meshes.h"
#include "test_mesh_input.h"

namespace osdoracle {
namespace {

// A path of `edges` edges from `start`, each step to the smallest-numbered neighbour not on the path
// yet: deterministic, and on the meshes used here never closes early.
std::vector<int> path_from(const FarInput& in, int start, int edges) {
    std::vector<std::set<int>> neighbours(in.positions.size());
    for (const auto& t : in.triangles)
        for (int i = 0; i < 3; ++i) {
            neighbours[t[i]].insert(t[(i + 1) % 3]);
            neighbours[t[(i + 1) % 3]].insert(t[i]);
        }
    std::vector<int> path{start};
    for (int e = 0; e < edges; ++e)
        for (int next : neighbours[path.back()])
            if (std::find(path.begin(), path.end(), next) == path.end()) {
                path.push_back(next);
                break;
            }
    return path;
}

// Tags the edges along `path` with the given sharpness values (one per edge, the last one repeated).
void sharpen_path(FarInput& in, const std::vector<int>& path, const std::vector<double>& sharpness) {
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        in.creases.push_back({path[i], path[i + 1], sharpness[std::min(i, sharpness.size() - 1)]});
}

constexpr double inf = infinite_sharpness;

// Vertex (x, y) of rgbtest::grid(nx, ny).
int grid_vertex(int nx, int x, int y) { return y * (nx + 1) + x; }

// grid(4, 3) with the interior row y = 1 and column x = 2 sharp: both chains meet the boundary at
// their ends (three sharp edges: corners) and cross at (2, 1) (four sharp edges: a corner).
FarInput grid_with_crossing_creases(std::vector<double> row_sharpness, std::vector<double> column_sharpness) {
    FarInput in = far_input(rgbtest::grid(4, 3));
    std::vector<int> row, column;
    for (int x = 0; x <= 4; ++x) row.push_back(grid_vertex(4, x, 1));
    for (int y = 0; y <= 3; ++y) column.push_back(grid_vertex(4, 2, y));
    sharpen_path(in, row, row_sharpness);
    sharpen_path(in, column, column_sharpness);
    return in;
}

}  // namespace

std::vector<CreaseCase> crease_cases() {
    std::vector<CreaseCase> cases;

    // Bipyramid equator (valence-4 crease vertices), apexes of valence 7 smooth.
    FarInput loop = far_input(rgbtest::bipyramid(7));
    for (int i = 0; i < 7; ++i) loop.creases.push_back({i, (i + 1) % 7, inf});
    cases.push_back({"crease_loop", loop});

    // Icosahedron chains of three edges (valence-5 crease vertices), ending in tagged corners or in
    // darts.
    FarInput corners = far_input(rgbtest::icosahedron());
    const std::vector<int> chain = path_from(corners, 0, 3);
    sharpen_path(corners, chain, {inf});
    FarInput darts = corners;
    corners.corners = {{chain.front(), inf}, {chain.back(), inf}};
    cases.push_back({"chain_ending_in_corners", corners});
    cases.push_back({"chain_ending_in_darts", darts});

    // One sharp edge from an apex of valence n to the equator: darts of valence n and 4.
    for (int n : {3, 4, 5, 6, 8}) {
        FarInput dart = far_input(rgbtest::bipyramid(n));
        dart.creases = {{n, 0, inf}};
        cases.push_back({"dart_valence" + std::to_string(n), dart});
    }

    // Open disc: a crease through the valence-7 centre (an irregular interior crease vertex) ending on
    // the boundary in corners, and a chain from the boundary into a grid ending in a dart.
    FarInput fan = far_input(rgbtest::fan(7));
    fan.creases = {{0, 1, inf}, {0, 4, inf}};
    cases.push_back({"crease_through_fan_centre", fan});
    FarInput grid_dart = far_input(rgbtest::grid(4, 3));
    sharpen_path(grid_dart, {grid_vertex(4, 0, 1), grid_vertex(4, 1, 1), grid_vertex(4, 2, 1)}, {inf});
    cases.push_back({"chain_from_boundary_ending_in_dart", grid_dart});

    // No tags, only the boundary option: the grid's two single-face corners become corners.
    FarInput cornered = far_input(rgbtest::grid(4, 3));
    cornered.boundary = BoundaryInterpolation::edge_and_corner;
    cases.push_back({"edge_and_corner_without_tags", cornered});

    FarInput crossing = grid_with_crossing_creases({inf}, {inf});
    cases.push_back({"creases_meeting_boundary", crossing});
    crossing.boundary = BoundaryInterpolation::edge_and_corner;
    cases.push_back({"creases_meeting_boundary_edge_and_corner", crossing});

    // Semi-sharp: a chain of sharpness 1, 3, 2 (crease ends change rule at different levels, to
    // darts and then to smooth), and a semi-sharp corner of sharpness 2 elsewhere.
    FarInput semi = far_input(rgbtest::icosahedron());
    const std::vector<int> semi_chain = path_from(semi, 0, 3);
    sharpen_path(semi, semi_chain, {1.0, 3.0, 2.0});
    for (int v = 0; v < static_cast<int>(semi.positions.size()); ++v)
        if (std::find(semi_chain.begin(), semi_chain.end(), v) == semi_chain.end()) {
            semi.corners = {{v, 2.0}};
            break;
        }
    cases.push_back({"semi_sharp_chain_1_3_2_and_corner_2", semi});

    // Equator loop with one edge of sharpness 3 and a sharpness-2 edge to the apex: the apex's
    // neighbour is a corner for two levels, then a crease; the apex a dart for two levels.
    FarInput mixed = far_input(rgbtest::bipyramid(6));
    for (int i = 0; i < 6; ++i) mixed.creases.push_back({i, (i + 1) % 6, i == 3 ? 3.0 : inf});
    mixed.creases.push_back({6, 0, 2.0});
    cases.push_back({"semi_sharp_corner_to_crease", mixed});

    // Three sharp edges at an apex, two of them of sharpness 1: a corner for one level, then a dart.
    FarInput corner_to_dart = far_input(rgbtest::bipyramid(5));
    corner_to_dart.creases = {{5, 0, inf}, {5, 2, 1.0}, {5, 3, 1.0}};
    cases.push_back({"semi_sharp_corner_to_dart", corner_to_dart});

    // Semi-sharp chains meeting the boundary: the ends are corners for as long as the chain is sharp.
    cases.push_back({"semi_sharp_meeting_boundary", grid_with_crossing_creases({2.0}, {1.0, 3.0})});
    return cases;
}

}  // namespace osdoracle
