#include "io/mesh_validation.h"

#include <algorithm>
#include <numeric>
#include <queue>

#include "io/obj_error.h"
#include "io/polygon_triangulation.h"

namespace rgbio {

namespace {

constexpr std::size_t kMaxListed = 5;  // non-manifold edges named in one message

std::string obj_index(std::uint32_t v) { return std::to_string(std::size_t(v) + 1); }

struct TriangleSoup {
    std::vector<rgb::Triangle> triangles;
    std::vector<std::size_t> lines;  // OBJ line of the face each triangle came from
};

TriangleSoup triangulate(const ObjRecords& records, const std::string& file, std::vector<std::string>& warnings) {
    TriangleSoup soup;
    std::size_t quads = 0, ngons = 0, from_polygons = 0;
    for (const ObjPolygon& polygon : records.polygons) {
        std::vector<std::uint32_t> sorted = polygon.vertices;
        std::sort(sorted.begin(), sorted.end());
        const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
        if (repeated != sorted.end())
            throw ObjError(ObjProblem::DegenerateFace, file, polygon.line,
                           "degenerate face: vertex " + obj_index(*repeated) + " appears twice");
        if (polygon.vertices.size() == 3) {
            soup.triangles.push_back({polygon.vertices[0], polygon.vertices[1], polygon.vertices[2]});
            soup.lines.push_back(polygon.line);
            continue;
        }
        ++(polygon.vertices.size() == 4 ? quads : ngons);
        for (const auto& t : triangulate_polygon(records.positions, polygon.vertices)) {
            soup.triangles.push_back(t);
            soup.lines.push_back(polygon.line);
            ++from_polygons;
        }
    }
    if (quads + ngons > 0)
        warnings.push_back("triangulated " + std::to_string(quads) + " quads and " + std::to_string(ngons) +
                           " polygons with more than 4 vertices into " + std::to_string(from_polygons) +
                           " triangles (ear clipping in each polygon's best-fit plane)");
    return soup;
}

void check_duplicates(const TriangleSoup& soup, const std::string& file) {
    std::vector<std::pair<rgb::Triangle, std::size_t>> keys(soup.triangles.size());
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
        rgb::Triangle k = soup.triangles[t];
        std::sort(k.begin(), k.end());
        keys[t] = {k, t};
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
        if (keys[i].first == keys[i - 1].first) {
            const std::size_t first = std::min(soup.lines[keys[i - 1].second], soup.lines[keys[i].second]);
            const std::size_t second = std::max(soup.lines[keys[i - 1].second], soup.lines[keys[i].second]);
            const rgb::Triangle& k = keys[i].first;
            throw ObjError(ObjProblem::DuplicateFace, file, second,
                           "duplicate face: triangle " + obj_index(k[0]) + " " + obj_index(k[1]) + " " + obj_index(k[2]) +
                               " also appears in the face on line " + std::to_string(first));
        }
}

// One (undirected edge, triangle) incidence; sorting groups the faces of each edge.
struct EdgeUse {
    std::uint32_t a, b;  // a < b
    std::uint32_t triangle;
    auto operator<=>(const EdgeUse&) const = default;
};

std::vector<EdgeUse> edge_uses(const std::vector<rgb::Triangle>& triangles) {
    std::vector<EdgeUse> uses;
    uses.reserve(3 * triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t p = triangles[t][i], q = triangles[t][(i + 1) % 3];
            uses.push_back({std::min(p, q), std::max(p, q), t});
        }
    std::sort(uses.begin(), uses.end());
    return uses;
}

// Calls f(begin, end) for each run of uses of one edge.
template <class F>
void for_each_edge(const std::vector<EdgeUse>& uses, F&& f) {
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i + 1;
        while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
        f(i, j);
        i = j;
    }
}

void check_edges(const TriangleSoup& soup, const std::vector<EdgeUse>& uses, const std::string& file) {
    std::vector<std::string> listed;
    std::size_t count = 0, first_line = 0;
    for_each_edge(uses, [&](std::size_t i, std::size_t j) {
        if (j - i <= 2) return;
        if (count++ == 0) first_line = soup.lines[uses[i].triangle];
        if (listed.size() == kMaxListed) return;
        std::string entry = "edge ";
        entry += obj_index(uses[i].a) + "-" + obj_index(uses[i].b) + " has " + std::to_string(j - i) + " faces (lines";
        for (std::size_t k = i; k < j; ++k) entry.append(" ").append(std::to_string(soup.lines[uses[k].triangle]));
        listed.push_back(entry + ")");
    });
    if (count == 0) return;
    std::string reason = std::to_string(count) + " non-manifold edge" + (count > 1 ? "s" : "") + " (more than two faces): ";
    for (std::size_t k = 0; k < listed.size(); ++k) reason += (k ? "; " : "") + listed[k];
    if (count > listed.size()) reason += "; ...";
    throw ObjError(ObjProblem::NonManifoldEdge, file, first_line, reason);
}

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }
    std::size_t find(std::size_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::size_t x, std::size_t y) { parent_[find(x)] = find(y); }

private:
    std::vector<std::size_t> parent_;
};

int corner_of(const rgb::Triangle& t, std::uint32_t v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; }

// A vertex is manifold when its faces form one fan, i.e. are connected through edges at the vertex.
void check_vertices(const TriangleSoup& soup, const std::vector<EdgeUse>& uses, std::size_t vertex_count,
                    const std::vector<std::size_t>& position_lines, const std::string& file) {
    const auto& tris = soup.triangles;
    UnionFind corners(3 * tris.size());
    for_each_edge(uses, [&](std::size_t i, std::size_t j) {
        if (j - i != 2) return;
        const std::uint32_t t1 = uses[i].triangle, t2 = uses[i + 1].triangle;
        for (std::uint32_t v : {uses[i].a, uses[i].b})
            corners.unite(3 * t1 + corner_of(tris[t1], v), 3 * t2 + corner_of(tris[t2], v));
    });
    std::vector<std::size_t> fan_root(vertex_count, SIZE_MAX);
    for (std::uint32_t t = 0; t < tris.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t v = tris[t][i];
            const std::size_t root = corners.find(3 * t + i);
            if (fan_root[v] == SIZE_MAX) fan_root[v] = root;
            else if (fan_root[v] != root)
                throw ObjError(ObjProblem::NonManifoldVertex, file, position_lines[v],
                               "non-manifold vertex " + obj_index(v) +
                                   " (bow-tie): its faces form separate fans that touch only at this vertex (faces on lines " +
                                   std::to_string(soup.lines[root / 3]) + " and " + std::to_string(soup.lines[t]) + ")");
        }
}

bool has_directed_edge(const rgb::Triangle& t, std::uint32_t from, std::uint32_t to) {
    const int i = corner_of(t, from);
    return t[i] == from && t[(i + 1) % 3] == to;
}

// Flips triangles so that every interior edge is traversed in opposite directions by its two faces.
// Each connected component keeps the orientation of the majority of its faces (on a tie, that of
// its first face in file order).
void orient(TriangleSoup& soup, const std::vector<EdgeUse>& uses, const std::string& file, std::vector<std::string>& warnings) {
    auto& tris = soup.triangles;
    const std::size_t n = tris.size();
    // For each triangle, its neighbours across interior edges and whether they agree in direction.
    std::vector<std::vector<std::pair<std::uint32_t, bool>>> neighbours(n);
    for_each_edge(uses, [&](std::size_t i, std::size_t j) {
        if (j - i != 2) return;
        const std::uint32_t t1 = uses[i].triangle, t2 = uses[i + 1].triangle;
        const bool same = has_directed_edge(tris[t1], uses[i].a, uses[i].b) == has_directed_edge(tris[t2], uses[i].a, uses[i].b);
        neighbours[t1].push_back({t2, same});
        neighbours[t2].push_back({t1, same});
    });
    constexpr std::uint8_t kUnvisited = 2;
    std::vector<std::uint8_t> flip(n, kUnvisited);
    std::size_t flipped = 0;
    for (std::uint32_t seed = 0; seed < n; ++seed) {
        if (flip[seed] != kUnvisited) continue;
        std::vector<std::uint32_t> component{seed};
        flip[seed] = 0;
        for (std::size_t k = 0; k < component.size(); ++k) {
            const std::uint32_t t = component[k];
            for (const auto& [u, same] : neighbours[t]) {
                const std::uint8_t wanted = flip[t] ^ static_cast<std::uint8_t>(same);
                if (flip[u] == kUnvisited) {
                    flip[u] = wanted;
                    component.push_back(u);
                } else if (flip[u] != wanted) {
                    throw ObjError(ObjProblem::NonOrientable, file, soup.lines[seed],
                                   "the surface containing this face cannot be oriented consistently (it is "
                                   "non-orientable, like a Moebius strip); conflict at the faces on lines " +
                                       std::to_string(soup.lines[t]) + " and " + std::to_string(soup.lines[u]));
                }
            }
        }
        const std::size_t ones = std::count_if(component.begin(), component.end(), [&](std::uint32_t t) { return flip[t] == 1; });
        const std::uint8_t flipped_value = 2 * ones > component.size() ? 0 : 1;
        for (std::uint32_t t : component)
            if (flip[t] == flipped_value) {
                std::swap(tris[t][1], tris[t][2]);
                ++flipped;
            }
    }
    if (flipped > 0)
        warnings.push_back("re-oriented " + std::to_string(flipped) + " of " + std::to_string(n) +
                           " faces so that neighbouring faces agree (each connected part keeps its majority orientation)");
}

LoadedMesh compact(const ObjRecords& records, TriangleSoup&& soup, std::vector<std::string>&& warnings) {
    LoadedMesh mesh;
    std::vector<std::uint32_t> new_index(records.positions.size(), UINT32_MAX);
    for (const rgb::Triangle& t : soup.triangles)
        for (std::uint32_t v : t) new_index[v] = 0;
    std::size_t unreferenced = 0, first_line = 0;
    for (std::size_t v = 0; v < new_index.size(); ++v) {
        if (new_index[v] == UINT32_MAX) {
            if (unreferenced++ == 0) first_line = records.position_lines[v];
            continue;
        }
        new_index[v] = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(records.positions[v]);
    }
    for (rgb::Triangle& t : soup.triangles)
        for (std::uint32_t& v : t) v = new_index[v];
    mesh.triangles = std::move(soup.triangles);
    if (unreferenced > 0)
        warnings.push_back("removed " + std::to_string(unreferenced) + " vertices used by no face (the first on line " +
                           std::to_string(first_line) + ") and renumbered the rest");
    mesh.warnings = std::move(warnings);
    return mesh;
}

}  // namespace

LoadedMesh validate_mesh(const ObjRecords& records, const std::string& file) {
    if (records.polygons.empty())
        throw ObjError(ObjProblem::NoFaces, file, 0,
                       "no faces: the file has " + std::to_string(records.positions.size()) + " vertices, " +
                           std::to_string(records.line_elements) + " line elements and " +
                           std::to_string(records.point_elements) + " point elements, but rgbsub needs a triangle surface");
    std::vector<std::string> warnings;
    if (records.line_elements + records.point_elements > 0)
        warnings.push_back("ignored " + std::to_string(records.line_elements) + " line elements (l) and " +
                           std::to_string(records.point_elements) + " point elements (p): only faces form the surface");
    TriangleSoup soup = triangulate(records, file, warnings);
    check_duplicates(soup, file);
    const std::vector<EdgeUse> uses = edge_uses(soup.triangles);
    check_edges(soup, uses, file);
    check_vertices(soup, uses, records.positions.size(), records.position_lines, file);
    orient(soup, uses, file, warnings);
    return compact(records, std::move(soup), std::move(warnings));
}

}  // namespace rgbio
