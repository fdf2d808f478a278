#include "io/formats/foreign_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "io/formats/exact_index.h"
#include "io/formats/exact_weld.h"
#include "io/obj/obj_error.h"
#include "io/obj/obj_parser.h"
#include "io/repair/mesh_validation.h"

namespace rgbio {

namespace {

void check_coordinates(const glm::dvec3& p, std::size_t vertex, const std::string& file) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(p[i]))
            throw ObjError(ObjProblem::NonFiniteCoordinate, file, 0, "vertex " + std::to_string(vertex + 1) + " has a non-finite coordinate");
        if (std::abs(p[i]) > kMaxCoordinate)
            throw ObjError(ObjProblem::AbsurdCoordinate, file, 0,
                           "vertex " + std::to_string(vertex + 1) + " has a coordinate beyond 1e12 (" + std::to_string(p[i]) + ")");
    }
}

// The file's vertices welded by position into records.positions (with their colours); per file
// vertex, its welded vertex (kNoIndex for a vertex no face uses, which is left out).
// Welded vertices are numbered in the file's vertex order (a file without split vertices keeps its
// numbering, as an OBJ does).
std::vector<std::uint32_t> weld_positions(const ForeignMesh& mesh, ObjRecords& records, const std::string& file,
                                          std::size_t& colour_conflicts, std::size_t& skin_conflicts) {
    std::vector<std::uint8_t> used(mesh.positions.size(), 0);
    for (std::uint32_t v : mesh.corners) {
        if (v >= mesh.positions.size())
            throw ObjError(ObjProblem::Malformed, file, 0,
                           "a face names vertex " + std::to_string(std::size_t(v) + 1) + " of " + std::to_string(mesh.positions.size()));
        used[v] = 1;
    }
    const std::vector<std::uint32_t> first = first_equal_points(mesh.positions, used);
    std::vector<std::uint32_t> welded(mesh.positions.size(), kNoIndex);
    records.positions.reserve(mesh.positions.size());
    records.position_lines.reserve(mesh.positions.size());
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        if (!used[v]) continue;
        const glm::dvec3& p = mesh.positions[v];
        check_coordinates(p, v, file);
        if (first[v] == v) {
            welded[v] = static_cast<std::uint32_t>(records.positions.size());
            records.positions.push_back(p);
            records.position_lines.push_back(std::size_t(v) + 1);
            if (!mesh.colours.empty()) records.colours.push_back(mesh.colours[v]);
        } else {
            welded[v] = welded[first[v]];
            colour_conflicts += !mesh.colours.empty() && records.colours[welded[v]] != mesh.colours[v];
            skin_conflicts += !mesh.influences.empty() && mesh.influences[first[v]] != mesh.influences[v];
        }
    }
    if (!records.colours.empty()) records.has_colour.assign(records.colours.size(), 1);
    return welded;
}

}  // namespace

void note_dropped(ForeignMesh& mesh, std::size_t n, const std::string& what) {
    if (n > 0) mesh.dropped.push_back(std::to_string(n) + " " + what);
}

void drop_idle_labels(ForeignMesh& mesh) {
    if (mesh.group_names.size() < 2) {
        mesh.group_names.clear();
        mesh.face_group.clear();
    }
    if (std::all_of(mesh.face_material.begin(), mesh.face_material.end(), [](std::uint32_t m) { return m == kNoIndex; }))
        mesh.face_material.clear();
}

std::string trimmed_message(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    return text;
}

void name_materials(std::vector<Material>& materials) {
    std::map<std::string, int> used;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        std::string& name = materials[i].name;
        if (name.empty()) name = "material " + std::to_string(i + 1);
        if (const int n = used[name]++; n > 0) name += " (" + std::to_string(n + 1) + ")";
    }
}

namespace {

// Faces left out of the records, with the first of each kind (1-based face numbers).
struct DroppedFaces {
    std::size_t degenerate = 0, duplicate = 0, first_degenerate = 0, first_duplicate = 0;
};

// The faces into records.polygons over the welded vertices, with their corners' texture coordinates
// (into records.texcoords), labels and face numbers as lines. Faces with a repeated vertex are left
// out; so are triangles over the vertices of an earlier one when `drop_duplicates`.
void add_polygons(const ForeignMesh& mesh, const std::vector<std::uint32_t>& welded, bool drop_duplicates, ObjRecords& records,
                  DroppedFaces& dropped) {
    const bool with_uvs = !mesh.corner_uvs.empty() || !mesh.vertex_uvs.empty();
    ExactIndex<2> uv_index(with_uvs ? records.positions.size() : 0);
    ExactIndex<3> triangle_index(drop_duplicates ? mesh.num_faces() : 0);
    std::vector<std::uint32_t> vertices, texcoords, sorted;
    records.polygons.reserve(mesh.num_faces(), mesh.corners.size());
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        vertices.clear();
        texcoords.clear();
        for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            vertices.push_back(welded[mesh.corners[c]]);
            if (!with_uvs) continue;
            const glm::dvec2 uv = mesh.corner_uvs.empty() ? mesh.vertex_uvs[mesh.corners[c]] : mesh.corner_uvs[c];
            bool added = false;
            texcoords.push_back(uv_index.number({uv.x, uv.y}, added));
            if (added) records.texcoords.push_back(uv);
        }
        if (vertices.size() < 3) continue;  // readers pass points and lines on as dropped, not as faces
        sorted.assign(vertices.begin(), vertices.end());
        if (sorted.size() == 3) {
            // Speed: most faces are triangles, which three swaps sort.
            if (sorted[0] > sorted[1]) std::swap(sorted[0], sorted[1]);
            if (sorted[1] > sorted[2]) std::swap(sorted[1], sorted[2]);
            if (sorted[0] > sorted[1]) std::swap(sorted[0], sorted[1]);
        } else {
            std::sort(sorted.begin(), sorted.end());
        }
        // Welding makes a face whose corners coincide (a sliver STL and scanners write) use a vertex
        // twice: it has no area and no place in a manifold.
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
            if (dropped.degenerate++ == 0) dropped.first_degenerate = f + 1;
            continue;
        }
        if (drop_duplicates && sorted.size() == 3) {
            bool added = false;
            triangle_index.number({double(sorted[0]), double(sorted[1]), double(sorted[2])}, added);
            if (!added) {
                if (dropped.duplicate++ == 0) dropped.first_duplicate = f + 1;
                continue;
            }
        }
        const std::uint32_t material = mesh.face_material.empty() ? kNoIndex : mesh.face_material[f];
        const std::uint32_t group = mesh.face_group.empty() ? kNoIndex : mesh.face_group[f];
        records.polygons.add(vertices, texcoords, f + 1, material, group, kNoIndex, 0);
    }
}

}  // namespace

LoadedMesh weld_foreign_mesh(ForeignMesh&& mesh, const std::string& file, const ReadOptions& options) {
    ObjRecords records;
    std::size_t colour_conflicts = 0, skin_conflicts = 0;
    const std::vector<std::uint32_t> welded = weld_positions(mesh, records, file, colour_conflicts, skin_conflicts);
    for (const Material& m : mesh.materials) records.material_names.push_back(m.name);
    records.group_names = mesh.group_names;
    // Speed: hashing every triangle to find duplicates took a tenth of reading a 1M-triangle file, and
    // the validation finds them anyway (by sorting, which it does for every file). So the duplicates
    // are dropped only when it finds one: the faces are then made again without them (validate_mesh
    // takes the positions only once it has passed that check).
    LoadedMesh loaded;
    DroppedFaces dropped;
    for (const bool drop_duplicates : {false, true}) {
        records.polygons = ObjPolygons();
        records.texcoords.clear();
        dropped = {};
        add_polygons(mesh, welded, drop_duplicates, records, dropped);
        if (records.polygons.empty())
            throw ObjError(ObjProblem::NoFaces, file, 0,
                           "no faces: the file has " + std::to_string(mesh.positions.size()) + " vertices and " +
                               std::to_string(mesh.num_faces()) + " faces" +
                               (dropped.degenerate > 0 ? " (all of them with coinciding corners)" : "") +
                               ", but rgbsub needs a triangle surface");
        try {
            loaded = validate_mesh(records, file, options);
            break;
        } catch (const ObjError& e) {
            if (e.problem() != ObjProblem::DuplicateFace || drop_duplicates) throw;
        }
    }
    std::vector<std::string> warnings = std::move(mesh.warnings);
    if (!mesh.dropped.empty()) {
        std::string text = "dropped what rgbsub does not keep: ";
        for (std::size_t i = 0; i < mesh.dropped.size(); ++i) text += (i > 0 ? "; " : "") + mesh.dropped[i];
        warnings.push_back(std::move(text));
    }
    if (dropped.degenerate > 0)
        warnings.push_back("dropped " + std::to_string(dropped.degenerate) + " faces whose corners coincide (the first is face " +
                           std::to_string(dropped.first_degenerate) + ")");
    if (dropped.duplicate > 0)
        warnings.push_back("dropped " + std::to_string(dropped.duplicate) +
                           " faces over the same three vertices as an earlier face (the first is face " + std::to_string(dropped.first_duplicate) +
                           "; a double-sided surface keeps its first side)");
    if (colour_conflicts > 0)
        warnings.push_back(std::to_string(colour_conflicts) +
                           " corners carry another colour than the first corner at their position: colours are kept per vertex, the first one wins");
    if (skin_conflicts > 0)
        warnings.push_back(std::to_string(skin_conflicts) +
                           " corners carry other joint weights than the first corner at their position: weights are kept per vertex, the first ones win");
    if (mesh.skeleton) {
        // Each loaded vertex from its welded vertex, which is the first file vertex at its position.
        loaded.skeleton = std::move(mesh.skeleton);
        loaded.influences.reserve(loaded.file_vertex.size());
        for (std::uint32_t r : loaded.file_vertex) loaded.influences.push_back(mesh.influences[records.position_lines[r] - 1]);
    }
    loaded.warnings.insert(loaded.warnings.begin(), warnings.begin(), warnings.end());
    loaded.materials = std::move(mesh.materials);
    return loaded;
}

}  // namespace rgbio
