#include "io/repair/mesh_validation.h"

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>

#include "io/obj/obj_error.h"
#include "io/repair/loaded_mesh_assembly.h"
#include "io/repair/manifold_repair.h"
#include "io/repair/polygon_triangulation.h"
#include "rgb/support/bucket_sort.h"

namespace rgbio {

namespace {

std::string obj_index(std::uint32_t v) { return std::to_string(std::size_t(v) + 1); }

TriangleSoup empty_soup(const ObjRecords& records) {
    TriangleSoup soup;
    soup.vertex_origin.resize(records.positions.size());
    std::iota(soup.vertex_origin.begin(), soup.vertex_origin.end(), 0u);
    return soup;
}

// The texture coordinates of the given corners of a polygon (kNoIndex where it has none).
std::array<std::uint32_t, 3> corner_texcoords(const ObjPolygon& polygon, const std::array<std::uint32_t, 3>& corners) {
    std::array<std::uint32_t, 3> uv{kNoIndex, kNoIndex, kNoIndex};
    if (!polygon.texcoords.empty())
        for (int i = 0; i < 3; ++i) uv[i] = polygon.texcoords[corners[i]];
    return uv;
}

// Appends the triangle of the given corners of polygon p (with_texcoords: some face has them).
void add_triangle(TriangleSoup& soup, const ObjRecords& records, bool with_texcoords, std::uint32_t p,
                  const std::array<std::uint32_t, 3>& corners) {
    const ObjPolygon polygon = records.polygons[p];
    soup.triangles.push_back({polygon.vertices[corners[0]], polygon.vertices[corners[1]], polygon.vertices[corners[2]]});
    if (with_texcoords) soup.texcoords.push_back(corner_texcoords(polygon, corners));
    soup.polygons.push_back(p);
    soup.lines.push_back(polygon.line);
}

TriangleSoup triangulate(const ObjRecords& records, const std::string& file, std::vector<std::string>& warnings) {
    TriangleSoup soup = empty_soup(records);
    const bool with_texcoords = records.polygons.has_texcoords();
    // A triangle per polygon at least (all of them for a triangle mesh): grown by doubling, the four
    // arrays were copied some twenty times each on the way to a million.
    const std::size_t polygons = records.polygons.size();
    soup.triangles.reserve(polygons);
    if (with_texcoords) soup.texcoords.reserve(polygons);
    soup.polygons.reserve(polygons);
    soup.lines.reserve(polygons);
    std::size_t quads = 0, ngons = 0, from_polygons = 0;
    std::vector<std::uint32_t> sorted;
    for (std::uint32_t p = 0; p < records.polygons.size(); ++p) {
        const ObjPolygon polygon = records.polygons[p];
        sorted.assign(polygon.vertices.begin(), polygon.vertices.end());
        std::sort(sorted.begin(), sorted.end());
        const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
        if (repeated != sorted.end())
            throw ObjError(ObjProblem::DegenerateFace, file, polygon.line,
                           "degenerate face: vertex " + obj_index(*repeated) + " appears twice");
        if (polygon.vertices.size() == 3) {
            add_triangle(soup, records, with_texcoords, p, {0, 1, 2});
            continue;
        }
        ++(polygon.vertices.size() == 4 ? quads : ngons);
        const auto triangles = triangulate_polygon_corners(records.positions, polygon.vertices);
        if (triangles.empty())
            throw ObjError(ObjProblem::ComplexPolygon, file, polygon.line,
                           "the polygon with " + std::to_string(polygon.vertices.size()) +
                               " vertices is too tangled (self-intersecting) to triangulate in reasonable time; "
                               "split it into simple polygons");
        for (const auto& t : triangles) {
            add_triangle(soup, records, with_texcoords, p, t);
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
    using Key = std::pair<rgb::Triangle, std::size_t>;  // the triangle's corners sorted, its index
    auto each_key = [&](auto&& emit) {
        for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
            rgb::Triangle k = soup.triangles[t];
            std::sort(k.begin(), k.end());
            emit(k[0], Key{k, t});
        }
    };
    const std::vector<Key> keys = rgb::sorted_by_bucket<Key>(soup.vertex_origin.size(), each_key, std::less<Key>());
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

// Flips triangles so that every interior edge is traversed in opposite directions by its two faces.
// Each connected component keeps the orientation of the majority of its faces (on a tie, that of
// its first face in file order).
void orient(TriangleSoup& soup, const std::vector<EdgeUse>& uses, const std::string& file, std::vector<std::string>& warnings) {
    const auto& tris = soup.triangles;
    const std::size_t n = tris.size();
    // For each triangle, its neighbours across interior edges (at most three, in three slots: a list
    // per triangle was a heap allocation each) and whether they agree in direction.
    struct Neighbour {
        std::uint32_t triangle;
        bool same;
    };
    std::vector<std::array<Neighbour, 3>> neighbours(n);
    std::vector<std::uint8_t> neighbour_count(n, 0);
    for_each_edge(uses, [&](std::size_t i, std::size_t j) {
        if (j - i != 2) return;
        const std::uint32_t t1 = uses[i].triangle, t2 = uses[i + 1].triangle;
        const bool same = has_directed_edge(tris[t1], uses[i].a, uses[i].b) == has_directed_edge(tris[t2], uses[i].a, uses[i].b);
        neighbours[t1][neighbour_count[t1]++] = {t2, same};
        neighbours[t2][neighbour_count[t2]++] = {t1, same};
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
            for (std::uint8_t slot = 0; slot < neighbour_count[t]; ++slot) {
                const auto [u, same] = neighbours[t][slot];
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
                soup.flip(t);
                ++flipped;
            }
    }
    if (flipped > 0)
        warnings.push_back("re-oriented " + std::to_string(flipped) + " of " + std::to_string(n) +
                           " faces so that neighbouring faces agree (each connected part keeps its majority orientation)");
}

}  // namespace

LoadedMesh validate_mesh(ObjRecords& records, const std::string& file, const ReadOptions& options) {
    if (records.polygons.empty())
        throw ObjError(ObjProblem::NoFaces, file, 0,
                       "no faces: the file has " + std::to_string(records.positions.size()) + " vertices, " +
                           std::to_string(records.line_elements) + " line elements and " +
                           std::to_string(records.point_elements) + " point elements, but rgbsub needs a triangle surface");
    std::vector<std::string> warnings;
    TriangleSoup soup = triangulate(records, file, warnings);
    check_duplicates(soup, file);
    const std::vector<EdgeUse> uses = make_manifold(soup, records.position_lines, file, options.strict, warnings);
    orient(soup, uses, file, warnings);
    return assemble_loaded_mesh(records, std::move(soup), std::move(warnings));
}

LoadedMesh saved_mesh_content(ObjRecords& records, std::vector<rgb::Triangle> triangles) {
    TriangleSoup soup = empty_soup(records);
    // Lines stay empty: only repairs report them. Each triangle is its own polygon, which only
    // labels look up (none: no array of millions of indices for nothing).
    soup.triangles = std::move(triangles);
    if (records.polygons.has_any_labels()) {
        soup.polygons.resize(records.polygons.size());
        std::iota(soup.polygons.begin(), soup.polygons.end(), 0u);
    }
    if (records.polygons.has_texcoords()) {
        soup.texcoords.reserve(records.polygons.size());
        for (std::uint32_t p = 0; p < records.polygons.size(); ++p) soup.texcoords.push_back(corner_texcoords(records.polygons[p], {0, 1, 2}));
    }
    return assemble_loaded_mesh(records, std::move(soup), {});
}

}  // namespace rgbio
