#include "rgb/mesh/navigation.h"

#include "rgb/mesh/mesh.h"

namespace rgb {

HalfedgeId canonical_outgoing(const Mesh& mesh, VertexId v) {
    const HalfedgeId start = mesh.vertex_halfedge(v);
    if (mesh.is_boundary(v)) return start;
    HalfedgeId best = start;
    for (HalfedgeId h = mesh.ccw_rotated(start); h != start; h = mesh.ccw_rotated(h))
        if (mesh.to_vertex(h) < mesh.to_vertex(best)) best = h;
    return best;
}

std::optional<VertexId> turn_ccw(const Mesh& mesh, VertexId c, VertexId from, int units) {
    HalfedgeId h = mesh.find_halfedge(c, from);
    if (!h.valid()) return std::nullopt;
    int acc = 0;
    while (true) {
        acc += mesh.angle(Mesh::face(h), Mesh::corner(h));
        if (acc == units) return mesh.from_vertex(Mesh::prev(h));
        if (acc > units) return std::nullopt;
        h = mesh.ccw_rotated(h);
        if (!h.valid()) return std::nullopt;
    }
}

std::optional<VertexId> turn_cw(const Mesh& mesh, VertexId c, VertexId from, int units) {
    // Incoming halfedge from->c: its face lies clockwise of the direction c->from.
    HalfedgeId g = mesh.find_halfedge(from, c);
    if (!g.valid()) return std::nullopt;
    int acc = 0;
    while (true) {
        const HalfedgeId out = Mesh::next(g);  // c -> third vertex
        acc += mesh.angle(Mesh::face(out), Mesh::corner(out));
        if (acc == units) return mesh.to_vertex(out);
        if (acc > units) return std::nullopt;
        g = mesh.opposite(out);
        if (!g.valid()) return std::nullopt;
    }
}

std::optional<VertexId> walk_straight(const Mesh& mesh, VertexId from, VertexId to, int max_level) {
    VertexId prev = from, cur = to;
    while (mesh.level(cur) > max_level) {
        auto next = turn_ccw(mesh, cur, prev, 6);
        if (!next) next = turn_cw(mesh, cur, prev, 6);
        if (!next) return std::nullopt;
        prev = cur;
        cur = *next;
    }
    return cur;
}

namespace {
// Every face around v must be at least of v's level, otherwise a coarser edge still crosses the ring.
bool star_reaches_level(const Mesh& mesh, VertexId v) {
    const HalfedgeId start = mesh.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        if (mesh.level(Mesh::face(h)) < mesh.level(v)) return false;
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    return true;
}
}  // namespace

bool ring_is_direct(const Mesh& mesh, VertexId v) {
    const HalfedgeId start = mesh.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        const FaceId f = Mesh::face(h);
        if (mesh.colour(f) != Colour::Green || mesh.level(f) != mesh.level(v)) return false;
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    return true;
}

namespace {
// When every face around v is a green triangle of v's own level, the ring is just v's neighbours.
bool direct_ring(const Mesh& mesh, VertexId v, std::vector<VertexId>& ring) {
    const int l = mesh.level(v);
    const HalfedgeId start = mesh.vertex_halfedge(v);
    HalfedgeId h = start, last = start;
    do {
        const FaceId f = Mesh::face(h);
        if (mesh.colour(f) != Colour::Green || mesh.level(f) != l) return false;
        ring.push_back(mesh.to_vertex(h));
        last = h;
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    if (!h.valid()) {
        // Boundary: its ring is the two boundary neighbours.
        const VertexId far = mesh.from_vertex(Mesh::prev(last));
        ring = {ring.front(), far};
    }
    return true;
}
}  // namespace

std::vector<VertexId> uniform_ring(const Mesh& mesh, VertexId v) {
    const int l = mesh.level(v);
    std::vector<VertexId> ring;
    if (direct_ring(mesh, v, ring)) return ring;
    ring.clear();
    if (!star_reaches_level(mesh, v)) return {};
    const HalfedgeId start = canonical_outgoing(mesh, v);
    if (mesh.is_boundary(v)) {
        HalfedgeId last = start;
        for (HalfedgeId h = mesh.ccw_rotated(start); h.valid(); h = mesh.ccw_rotated(h)) last = h;
        for (VertexId dir : {mesh.to_vertex(start), mesh.from_vertex(Mesh::prev(last))}) {
            auto w = walk_straight(mesh, v, dir, l);
            if (!w) return {};
            ring.push_back(*w);
        }
        return ring;
    }
    // Red edges point in directions 30 degrees off the uniform ones: start from a green edge.
    HalfedgeId green = start;
    while (mesh.edge_type(green).colour != Colour::Green) {
        green = mesh.ccw_rotated(green);
        if (green == start) return {};
    }
    const VertexId first = mesh.to_vertex(green);
    const int n = mesh.uniform_valence(v);
    ring.reserve(static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r) {
        auto dir = r == 0 ? std::optional<VertexId>(first) : turn_ccw(mesh, v, first, 2 * r);
        if (!dir) return {};
        auto w = walk_straight(mesh, v, *dir, l);
        if (!w) return {};
        ring.push_back(*w);
    }
    return ring;
}

}  // namespace rgb
