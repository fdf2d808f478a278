#include "rgb/mesh/invariants.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"
#include "rgb/support/parallel.h"

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
    const FaceCorners place = face_corners(mesh, f);
    const int l = mesh.level(f);
    const CornerNumerators parent = parent_corners(place, l), corners = corners_at(place, l + 1);
    int corners_of_parent = 0;
    for (const auto& c : corners) corners_of_parent += static_cast<int>(std::count(parent.begin(), parent.end(), c));
    const int want = mesh.colour(f) == Colour::Green ? 3 : (mesh.colour(f) == Colour::Red ? 2 : 1);
    if (corners_of_parent != want)
        report(face_name(mesh, f) + " does not fit its triangle of level " + std::to_string(l) + ": " +
               std::to_string(corners_of_parent) + " of its corners are the triangle's, expected " + std::to_string(want));
}

void check_face(const Mesh& mesh, FaceId f, Reporter& report, const KnownInvariants& known) {
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
    if (levels_fit && !known.hierarchy_place) {
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
        // Adjacency agrees from both sides, so the edge's two types need comparing once.
        if (h < o && mesh.edge_type(h) != mesh.edge_type(o)) {
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
    // Built only for a report: this runs for every vertex of every mesh checked.
    auto name = [&] { return "vertex " + std::to_string(v.idx) + " (level " + std::to_string(mesh.level(v)) + ")"; };
    const HalfedgeId start = mesh.vertex_halfedge(v);
    if (!start.valid() || !mesh.is_live(Mesh::face(start)) || mesh.from_vertex(start) != v) {
        report(name() + " has no valid outgoing halfedge");
        return;
    }
    if (mesh.is_boundary(v) != mesh.is_boundary(start)) report(name() + ": boundary flag disagrees with its star");
    int angles = 0, faces = 0;
    HalfedgeId h = start;
    do {
        if (mesh.from_vertex(h) != v) {
            report(name() + ": its star is not a fan around it");
            return;
        }
        angles += mesh.angle(Mesh::face(h), Mesh::corner(h));
        ++faces;
        if (faces > 1000) {
            report(name() + ": star does not close");
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
        report(name() + ": topological angles sum to " + std::to_string(angles) + ", expected " + std::to_string(want));
}

struct Tally {
    std::size_t live = 0;
    std::size_t star_corners = 0;  // corners met walking around the vertices
};

// Runs check(id, report, tally) on every live element with ids below `capacity`, in parallel blocks
// with a report each, joined in id order: the report lists the same first violations a plain loop
// would.
template <class Id, class Check>
Tally check_each(const Mesh& mesh, std::size_t capacity, std::size_t max_reports, InvariantReport& result, const Check& check) {
    const std::size_t blocks = parallel_blocks(capacity, 1 << 14);
    std::vector<InvariantReport> reports(blocks);
    std::vector<Tally> tallies(blocks);
    parallel_blocks_for(capacity, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
        Reporter report(reports[b], max_reports);
        for (std::size_t i = begin; i < end; ++i) {
            const Id id(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(id)) continue;
            ++tallies[b].live;
            check(id, report, tallies[b]);
        }
    });
    Reporter report(result, max_reports);
    Tally total;
    for (std::size_t b = 0; b < blocks; ++b) {
        for (const std::string& violation : reports[b].violations) report(violation);
        total.live += tallies[b].live;
        total.star_corners += tallies[b].star_corners;
    }
    return total;
}

}  // namespace

InvariantReport check_normal_form(const Mesh& mesh, std::size_t max_reports) {
    InvariantReport result;
    check_each<FaceId>(mesh, mesh.face_capacity(), max_reports, result, [&](FaceId f, Reporter& report, Tally&) {
        if (!in_normal_form(mesh, f))
            report(face_name(mesh, f) + ": in a parent with two split edges, its red edge leaves its top vertex (normal form: enters it)");
    });
    return result;
}

InvariantReport check_invariants(const Mesh& mesh, std::size_t max_reports, KnownInvariants known) {
    InvariantReport result;
    const Tally faces = check_each<FaceId>(mesh, mesh.face_capacity(), max_reports, result,
                                           [&](FaceId f, Reporter& report, Tally&) { check_face(mesh, f, report, known); });
    const Tally vertices = check_each<VertexId>(mesh, mesh.vertex_capacity(), max_reports, result, [&](VertexId v, Reporter& report, Tally& tally) {
        check_vertex(mesh, v, report, tally.star_corners);
    });
    Reporter report(result, max_reports);
    if (faces.live != mesh.num_faces()) report("live face count " + std::to_string(faces.live) + " != num_faces()");
    if (vertices.live != mesh.num_vertices()) report("live vertex count " + std::to_string(vertices.live) + " != num_vertices()");
    if (vertices.star_corners != 3 * faces.live)
        report("vertex stars cover " + std::to_string(vertices.star_corners) + " corners, expected " + std::to_string(3 * faces.live) +
               " (a face unreachable from its vertices: non-manifold)");
    return result;
}

}  // namespace rgb
