#include "cli/mesh_summary.h"

#include <vector>

namespace cli {

MeshSummary summarize(const rgb::Mesh& mesh) {
    MeshSummary s;
    s.vertices = mesh.num_vertices();
    s.faces = mesh.num_faces();
    std::size_t interior_halfedges = 0;
    // In a manifold mesh each boundary vertex starts exactly one boundary halfedge, so following
    // "the boundary halfedge leaving the end vertex" walks each loop once.
    std::vector<rgb::HalfedgeId> boundary_out(mesh.vertex_capacity());
    std::vector<rgb::HalfedgeId> boundary;
    for (rgb::FaceId f : mesh.faces()) {
        const rgb::FaceType& type = mesh.type(f);
        ++(type.colour == rgb::Colour::Green ? s.green : type.colour == rgb::Colour::Red ? s.red : s.blue);
        ++s.faces_per_level[type.level];
        for (int c = 0; c < 3; ++c) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, c);
            if (!mesh.is_boundary(h)) {
                ++interior_halfedges;
                continue;
            }
            boundary_out[mesh.from_vertex(h).idx] = h;
            boundary.push_back(h);
        }
    }
    s.edges = interior_halfedges / 2 + boundary.size();
    std::vector<std::uint8_t> visited(3 * mesh.face_capacity(), 0);
    for (rgb::HalfedgeId start : boundary) {
        if (visited[start.idx]) continue;
        ++s.boundary_loops;
        for (rgb::HalfedgeId h = start; h.valid() && !visited[h.idx]; h = boundary_out[mesh.to_vertex(h).idx]) visited[h.idx] = 1;
    }
    s.euler_characteristic = static_cast<long>(s.vertices) - static_cast<long>(s.edges) + static_cast<long>(s.faces);
    return s;
}

void print_summary(std::ostream& out, const MeshSummary& s) {
    out << "vertices: " << s.vertices << "\nedges: " << s.edges << "\nfaces: " << s.faces << "\nboundary loops: " << s.boundary_loops
        << "\nEuler characteristic: " << s.euler_characteristic << "\ntriangles per colour: green " << s.green << ", red " << s.red
        << ", blue " << s.blue << "\ntriangles per level:";
    for (const auto& [level, count] : s.faces_per_level) out << ' ' << level << ':' << count;
    out << '\n';
}

}  // namespace cli
