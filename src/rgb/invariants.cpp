#include "rgb/invariants.h"

#include <string>

#include "rgb/mesh.h"

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

void check_face(const Mesh& mesh, FaceId f, Reporter& report) {
    const int l = mesh.level(f);
    const FaceType& t = mesh.type(f);
    int high = 0;
    for (VertexId v : mesh.face_vertices(f)) {
        if (!mesh.is_live(v)) report(face_name(mesh, f) + " uses dead vertex " + std::to_string(v.idx));
        if (mesh.level(v) > l + 1) report(face_name(mesh, f) + " has vertex " + std::to_string(v.idx) + " two levels finer");
        high += mesh.level(v) == l + 1;
    }
    const int want_high = t.colour == Colour::Green ? 0 : (t.colour == Colour::Red ? 1 : 2);
    if (high != want_high)
        report(face_name(mesh, f) + " has " + std::to_string(high) + " vertices of level l+1, expected " + std::to_string(want_high));
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
