#include "rgb/invariants.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rgb/face_location.h"
#include "rgb/mesh.h"
#include "rgb/operators.h"

namespace rgb {

namespace {

class Reporter {
public:
    Reporter(InvariantReport& r, std::size_t max) : report_(r), max_(max) {}
    void operator()(const std::string& s) {
        if (report_.violations.size() < max_) report_.violations.push_back(s);
    }
private:
    InvariantReport& report_;
    std::size_t max_;
};

std::string face_name(const Mesh& mesh, FaceId f) {
    const auto& v = mesh.face_vertices(f);
    const char* colour = colour_name(mesh.colour(f));
    return std::string("face ") + std::to_string(f.idx) + " (" + colour + " level " + std::to_string(mesh.level(f)) +
           ", vertices " + std::to_string(v[0].idx) + " " + std::to_string(v[1].idx) + " " + std::to_string(v[2].idx) + ")";
}

// Every face is a piece of a triangle T of Σl (l its level), and its corners are where its colour says
// (spec §1.3): a green face is T; a red one has two corners of T and a midpoint of T's edge between
// them; a blue one has one corner of T and two midpoints. This ties the levels to the geometry.
void check_hierarchy_place(const Mesh& mesh, FaceId f, Reporter& report) {
    const std::uint32_t b = base_face_of(mesh, f);
    const auto parent = parent_triangle(mesh, f, b);
    const int l = mesh.level(f);
    int corners_of_parent = 0;
    for (VertexId v : mesh.face_vertices(f)) {
        const auto p = in_face(mesh.base(), mesh.address(v), b);
        if (!p) continue;
        for (const SurfacePoint& c : parent)
            if (*p == c) ++corners_of_parent;
    }
    const int want = mesh.colour(f) == Colour::Green ? 3 : (mesh.colour(f) == Colour::Red ? 2 : 1);
    if (corners_of_parent != want)
        report(face_name(mesh, f) + " does not fit its triangle of level " + std::to_string(l) + ": " +
               std::to_string(corners_of_parent) + " of its corners are the triangle's, expected " + std::to_string(want));
}

void check_face(const Mesh& mesh, FaceId f, Reporter& report) {
    const int l = mesh.level(f);
    const FaceType& t = mesh.type(f);
    int high = 0;
    bool levels_fit = true;
    for (VertexId v : mesh.face_vertices(f)) {
        if (!mesh.is_live(v)) {
            report(face_name(mesh, f) + " uses dead vertex " + std::to_string(v.idx));
            return;
        }
        if (mesh.level(v) > l + 1) {
            report(face_name(mesh, f) + " has vertex " + std::to_string(v.idx) + " two levels finer");
            levels_fit = false;
        }
        high += mesh.level(v) == l + 1;
    }
    const int want_high = t.colour == Colour::Green ? 0 : (t.colour == Colour::Red ? 1 : 2);
    if (high != want_high)
        report(face_name(mesh, f) + " has " + std::to_string(high) + " vertices of level l+1, expected " + std::to_string(want_high));
    if (levels_fit) {
        try {
            check_hierarchy_place(mesh, f, report);
        } catch (const std::logic_error&) {
            report(face_name(mesh, f) + " lies in no single base face");
        }
    }
    if (t.colour != Colour::Green) {
        if (t.red_edge > 2) report(face_name(mesh, f) + " has red edge index " + std::to_string(t.red_edge));
        const HalfedgeId red = Mesh::halfedge(f, t.red_edge % 3);
        const int ends_high = (mesh.level(mesh.from_vertex(red)) > l) + (mesh.level(mesh.to_vertex(red)) > l);
        if (ends_high != 1) report(face_name(mesh, f) + ": its red edge must join a coarse vertex and a level-l+1 vertex");
    }
    for (int i = 0; i < 3; ++i) {
        const HalfedgeId h = Mesh::halfedge(f, i);
        const HalfedgeId o = mesh.opposite(h);
        if (!o.valid()) continue;
        if (!mesh.is_live(Mesh::face(o)) || mesh.opposite(o) != h || mesh.from_vertex(o) != mesh.to_vertex(h) ||
            mesh.to_vertex(o) != mesh.from_vertex(h)) {
            report(face_name(mesh, f) + " edge " + std::to_string(i) + ": broken adjacency");
            continue;
        }
        if (mesh.edge_type(h) != mesh.edge_type(o)) {
            const EdgeType a = mesh.edge_type(h), b = mesh.edge_type(o);
            report("edge " + std::to_string(mesh.from_vertex(h).idx) + "-" + std::to_string(mesh.to_vertex(h).idx) + " is " +
                   colour_name(a.colour) + " level " + std::to_string(a.level) + " in " + face_name(mesh, f) + " but " +
                   colour_name(b.colour) + " level " + std::to_string(b.level) + " in " + face_name(mesh, Mesh::face(o)));
        }
        if (t.colour == Colour::Blue && i == t.red_edge && mesh.colour(Mesh::face(o)) == Colour::Blue &&
            mesh.level(Mesh::face(o)) == l && h < o)
            report(face_name(mesh, f) + " and " + face_name(mesh, Mesh::face(o)) + " are blues sharing their red edge");
    }
}

void check_vertex(const Mesh& mesh, VertexId v, Reporter& report, std::size_t& star_total) {
    const std::string name = "vertex " + std::to_string(v.idx) + " (level " + std::to_string(mesh.level(v)) + ")";
    const HalfedgeId start = mesh.vertex_halfedge(v);
    if (!start.valid() || !mesh.is_live(Mesh::face(start)) || mesh.from_vertex(start) != v) {
        report(name + " has no valid outgoing halfedge");
        return;
    }
    if (mesh.is_boundary(v) != mesh.is_boundary(start)) report(name + ": boundary flag disagrees with its star");
    int angles = 0, faces = 0;
    HalfedgeId h = start;
    do {
        if (mesh.from_vertex(h) != v) {
            report(name + ": its star is not a fan around it");
            return;
        }
        angles += mesh.angle(Mesh::face(h), Mesh::corner(h));
        ++faces;
        if (faces > 1000) {
            report(name + ": star does not close");
            return;
        }
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    star_total += static_cast<std::size_t>(faces);
    const bool boundary = !h.valid();
    int want;
    if (mesh.level(v) == 0) want = boundary ? 2 * (mesh.uniform_valence(v) - 1) : 2 * mesh.uniform_valence(v);
    else want = boundary ? 6 : 12;
    if (angles != want)
        report(name + ": topological angles sum to " + std::to_string(angles) + ", expected " + std::to_string(want));
}

}  // namespace

InvariantReport check_normal_form(const Mesh& mesh, std::size_t max_reports) {
    InvariantReport result;
    Reporter report(result, max_reports);
    for (FaceId f : mesh.faces())
        if (!in_normal_form(mesh, f))
            report(face_name(mesh, f) + ": in a parent with two split edges, its red edge leaves its top vertex (normal form: enters it)");
    return result;
}

InvariantReport check_invariants(const Mesh& mesh, std::size_t max_reports) {
    InvariantReport result;
    Reporter report(result, max_reports);
    std::size_t faces = 0, vertices = 0, star_total = 0;
    for (FaceId f : mesh.faces()) {
        ++faces;
        check_face(mesh, f, report);
    }
    for (VertexId v : mesh.vertices()) {
        ++vertices;
        check_vertex(mesh, v, report, star_total);
    }
    if (faces != mesh.num_faces()) report("live face count " + std::to_string(faces) + " != num_faces()");
    if (vertices != mesh.num_vertices()) report("live vertex count " + std::to_string(vertices) + " != num_vertices()");
    if (star_total != 3 * faces)
        report("vertex stars cover " + std::to_string(star_total) + " corners, expected " + std::to_string(3 * faces) +
               " (a face unreachable from its vertices: non-manifold)");
    return result;
}

}  // namespace rgb
