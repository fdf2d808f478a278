#include "support/test_meshes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "support/obj_reader.h"

namespace rgbtest {
namespace {

// Deterministic jitter in [-amplitude, amplitude] per coordinate. Uses the raw mt19937 stream, which
// the standard fixes, rather than a distribution, whose output differs between standard libraries.
void jitter(std::vector<glm::dvec3>& positions, double amplitude, std::uint32_t seed) {
    std::mt19937 rng(seed);
    for (glm::dvec3& p : positions)
        for (int i = 0; i < 3; ++i) p[i] += amplitude * (2.0 * (rng() / 4294967296.0) - 1.0);
}

// Orients every triangle of a convex polyhedron around the origin counter-clockwise seen from outside.
void orient_outward(TestMesh& m) {
    for (rgb::Triangle& t : m.triangles) {
        const glm::dvec3& a = m.positions[t[0]];
        const glm::dvec3& b = m.positions[t[1]];
        const glm::dvec3& c = m.positions[t[2]];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0) std::swap(t[1], t[2]);
    }
}

// All triples of vertices pairwise at distance `edge` (the faces of a regular convex polyhedron).
std::vector<rgb::Triangle> triples_at_distance(const std::vector<glm::dvec3>& p, double edge) {
    const auto n = static_cast<std::uint32_t>(p.size());
    auto adjacent = [&](std::uint32_t i, std::uint32_t j) { return std::abs(glm::distance(p[i], p[j]) - edge) < 1e-9; };
    std::vector<rgb::Triangle> triangles;
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = i + 1; j < n; ++j)
            for (std::uint32_t k = j + 1; k < n; ++k)
                if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) triangles.push_back({i, j, k});
    return triangles;
}

}  // namespace

rgb::Mesh make_rgb_mesh(const TestMesh& m) { return rgb::Mesh(m.positions, m.triangles); }

double bounding_box_diagonal(const std::vector<glm::dvec3>& positions) {
    glm::dvec3 lo = positions.front();
    glm::dvec3 hi = positions.front();
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::distance(lo, hi);
}

TestMesh tetrahedron() {
    return {"tetrahedron",
            {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
            {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
}

TestMesh octahedron() {
    TestMesh m{"octahedron", {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, {}};
    m.triangles = triples_at_distance(m.positions, std::sqrt(2.0));
    orient_outward(m);
    jitter(m.positions, 0.2, 11);
    return m;
}

TestMesh icosahedron() {
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    TestMesh m{"icosahedron", {}, {}};
    for (double s : {-1.0, 1.0})
        for (double t : {-1.0, 1.0}) {
            m.positions.push_back({0, s, t * phi});
            m.positions.push_back({s, t * phi, 0});
            m.positions.push_back({t * phi, 0, s});
        }
    m.triangles = triples_at_distance(m.positions, 2.0);
    orient_outward(m);
    jitter(m.positions, 0.15, 12);
    return m;
}

TestMesh bipyramid(int n) {
    TestMesh m{"bipyramid" + std::to_string(n), {}, {}};
    const auto un = static_cast<std::uint32_t>(n);
    for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / n;
        m.positions.push_back({std::cos(angle), std::sin(angle), 0.0});
    }
    m.positions.push_back({0, 0, 1.3});
    m.positions.push_back({0, 0, -0.9});
    for (std::uint32_t i = 0; i < un; ++i) {
        m.triangles.push_back({i, (i + 1) % un, un});
        m.triangles.push_back({(i + 1) % un, i, un + 1});
    }
    orient_outward(m);
    jitter(m.positions, 0.1, 100 + un);
    return m;
}

rgb::BaseMesh tagged_bipyramid() {
    const TestMesh m = bipyramid(5);
    rgb::SharpFeatures features;
    features.edges = {{5, 0, 10}, {5, 2, 1}, {5, 3, 1}, {0, 1, 3}};
    return rgb::BaseMesh(m.positions, m.triangles, features);
}

TestMesh fan(int n) {
    TestMesh m{"fan" + std::to_string(n), {{0, 0, 0.3}}, {}};
    const auto un = static_cast<std::uint32_t>(n);
    for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / n;
        m.positions.push_back({std::cos(angle), std::sin(angle), 0.0});
    }
    for (std::uint32_t i = 0; i < un; ++i) m.triangles.push_back({0, i + 1, (i + 1) % un + 1});
    jitter(m.positions, 0.15, 200 + un);
    return m;
}

TestMesh grid(int nx, int ny) {
    TestMesh m{"grid" + std::to_string(nx) + "x" + std::to_string(ny), {}, {}};
    const auto row = static_cast<std::uint32_t>(nx + 1);
    for (int y = 0; y <= ny; ++y)
        for (int x = 0; x <= nx; ++x) m.positions.push_back({x, y, 0.0});
    for (std::uint32_t y = 0; y < static_cast<std::uint32_t>(ny); ++y)
        for (std::uint32_t x = 0; x < static_cast<std::uint32_t>(nx); ++x) {
            const std::uint32_t a = y * row + x, b = a + 1, c = a + row, d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    jitter(m.positions, 0.1, 300);
    return m;
}

namespace {

// Cells of an nx-by-ny grid: solid, or a hole every `every` cells (never on the rim).
bool is_hole(int x, int y, int nx, int ny, int every) {
    return every > 0 && x > 0 && y > 0 && x < nx - 1 && y < ny - 1 && x % every == every / 2 && y % every == every / 2;
}

}  // namespace

TestMesh perforated_slab(int nx, int ny, int every) {
    TestMesh m{"slab" + std::to_string(nx) + "x" + std::to_string(ny) + "h" + std::to_string(every), {}, {}};
    const auto row = static_cast<std::uint32_t>(nx + 1);
    const std::uint32_t layer = row * static_cast<std::uint32_t>(ny + 1);
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y <= ny; ++y)
            for (int x = 0; x <= nx; ++x) m.positions.push_back({x, y, 0.6 * z});
    auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {  // counter-clockwise
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
    };
    auto solid = [&](int x, int y) { return x >= 0 && y >= 0 && x < nx && y < ny && !is_hole(x, y, nx, ny, every); };
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            if (!solid(x, y)) continue;
            const std::uint32_t a = static_cast<std::uint32_t>(y) * row + static_cast<std::uint32_t>(x), b = a + 1, c = a + row + 1,
                                d = a + row;
            quad(a + layer, b + layer, c + layer, d + layer);  // top, facing +z
            quad(a, d, c, b);                                  // bottom, facing -z
            // Walls where a solid cell meets a hole or the outside, facing away from the cell.
            if (!solid(x, y - 1)) quad(a, b, b + layer, a + layer);
            if (!solid(x + 1, y)) quad(b, c, c + layer, b + layer);
            if (!solid(x, y + 1)) quad(c, d, d + layer, c + layer);
            if (!solid(x - 1, y)) quad(d, a, a + layer, d + layer);
        }
    // Drop the vertices no face uses (inside the holes' columns there are none, but keep it general).
    std::vector<std::uint32_t> index(m.positions.size(), UINT32_MAX);
    std::vector<glm::dvec3> used;
    for (rgb::Triangle& t : m.triangles)
        for (std::uint32_t& v : t) {
            if (index[v] == UINT32_MAX) {
                index[v] = static_cast<std::uint32_t>(used.size());
                used.push_back(m.positions[v]);
            }
            v = index[v];
        }
    m.positions = used;
    jitter(m.positions, 0.08, 500 + static_cast<std::uint32_t>(nx * ny));
    return m;
}

TestMesh grid_with_holes(int nx, int ny, int every) {
    TestMesh m{"holes" + std::to_string(nx) + "x" + std::to_string(ny) + "h" + std::to_string(every), {}, {}};
    const auto row = static_cast<std::uint32_t>(nx + 1);
    for (int y = 0; y <= ny; ++y)
        for (int x = 0; x <= nx; ++x) m.positions.push_back({x, y, 0.1 * ((x * 7 + y * 3) % 5)});
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            if (is_hole(x, y, nx, ny, every)) continue;
            const std::uint32_t a = static_cast<std::uint32_t>(y) * row + static_cast<std::uint32_t>(x), b = a + 1, c = a + row,
                                d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    jitter(m.positions, 0.1, 600 + static_cast<std::uint32_t>(nx * ny));
    return m;
}

TestMesh with_rotated_corners(const TestMesh& m) {
    TestMesh r = m;
    r.name += "-rotated";
    for (rgb::Triangle& t : r.triangles) t = {t[1], t[2], t[0]};
    return r;
}

TestMesh with_reversed_faces(const TestMesh& m) {
    TestMesh r = m;
    r.name += "-reversed";
    std::reverse(r.triangles.begin(), r.triangles.end());
    return r;
}

TestMesh with_shuffled_vertices(const TestMesh& m, std::uint32_t seed) {
    TestMesh r = m;
    r.name += "-shuffled";
    std::vector<std::uint32_t> to(m.positions.size());
    for (std::uint32_t i = 0; i < to.size(); ++i) to[i] = i;
    std::mt19937 rng(seed);
    for (std::size_t i = to.size(); i > 1; --i) std::swap(to[i - 1], to[rng() % i]);
    for (std::uint32_t i = 0; i < to.size(); ++i) r.positions[to[i]] = m.positions[i];
    for (rgb::Triangle& t : r.triangles)
        for (std::uint32_t& v : t) v = to[v];
    return r;
}

TestMesh torus(int around, int tube) {
    TestMesh m{"torus" + std::to_string(around) + "x" + std::to_string(tube), {}, {}};
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const double u = 2.0 * std::numbers::pi * i / around, v = 2.0 * std::numbers::pi * j / tube;
            m.positions.push_back({(1.0 + 0.4 * std::cos(v)) * std::cos(u), (1.0 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v)});
        }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * tube + (j % tube)); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

TestMesh single_triangle() { return {"triangle", {{0, 0, 0}, {1, 0, 0}, {0.3, 0.9, 0.1}}, {{0, 1, 2}}}; }

TestMesh bunny() {
    TestMesh m = read_obj(RGBSUB_ASSETS_DIR "/bunny.obj");
    m.name = "bunny";
    return m;
}

std::vector<TestMesh> small_meshes() {
    std::vector<TestMesh> meshes{tetrahedron(), octahedron(), icosahedron()};
    for (int n = 3; n <= 10; ++n) meshes.push_back(bipyramid(n));
    for (int n : {5, 6, 7}) meshes.push_back(fan(n));
    meshes.push_back(grid(3, 2));
    meshes.push_back(single_triangle());
    return meshes;
}

}  // namespace rgbtest
