#include "cli/mesh_summary.h"

#include <array>
#include <vector>

#include "rgb/support/parallel.h"
#include "rgb/values/triangle_quality.h"

namespace cli {

MeshSummary summarize(const rgb::Mesh& mesh) {
    MeshSummary s;
    s.vertices = mesh.num_vertices();
    s.faces = mesh.num_faces();
    // Counted in parallel blocks of face slots (a saved file has millions of faces), joined in order.
    struct Counts {
        std::size_t green = 0, red = 0, blue = 0, interior_halfedges = 0;
        std::array<std::size_t, 256> per_level{};
        std::vector<rgb::HalfedgeId> boundary;
    };
    std::vector<Counts> blocks(rgb::parallel_blocks(mesh.face_capacity(), 1 << 16));
    rgb::parallel_blocks_for(mesh.face_capacity(), blocks.size(), [&](std::size_t b, std::size_t begin, std::size_t end) {
        Counts& c = blocks[b];
        for (std::size_t i = begin; i < end; ++i) {
            const rgb::FaceId f(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(f)) continue;
            const rgb::FaceType& type = mesh.type(f);
            ++(type.colour == rgb::Colour::Green ? c.green : type.colour == rgb::Colour::Red ? c.red : c.blue);
            ++c.per_level[type.level];
            for (int k = 0; k < 3; ++k) {
                const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, k);
                if (mesh.is_boundary(h)) c.boundary.push_back(h);
                else ++c.interior_halfedges;
            }
        }
    });
    std::size_t interior_halfedges = 0;
    std::array<std::size_t, 256> per_level{};
    std::vector<rgb::HalfedgeId> boundary;
    for (const Counts& c : blocks) {
        s.green += c.green;
        s.red += c.red;
        s.blue += c.blue;
        interior_halfedges += c.interior_halfedges;
        for (std::size_t l = 0; l < per_level.size(); ++l) per_level[l] += c.per_level[l];
        boundary.insert(boundary.end(), c.boundary.begin(), c.boundary.end());
    }
    for (std::size_t l = 0; l < per_level.size(); ++l)
        if (per_level[l] > 0) s.faces_per_level[static_cast<int>(l)] = per_level[l];
    s.edges = interior_halfedges / 2 + boundary.size();
    s.euler_characteristic = static_cast<long>(s.vertices) - static_cast<long>(s.edges) + static_cast<long>(s.faces);
    if (boundary.empty()) return s;
    // In a manifold mesh each boundary vertex starts exactly one boundary halfedge, so following
    // "the boundary halfedge leaving the end vertex" walks each loop once.
    std::vector<rgb::HalfedgeId> boundary_out(mesh.vertex_capacity());
    for (rgb::HalfedgeId h : boundary) boundary_out[mesh.from_vertex(h).idx] = h;
    std::vector<std::uint8_t> visited(3 * mesh.face_capacity(), 0);
    for (rgb::HalfedgeId start : boundary) {
        if (visited[start.idx]) continue;
        ++s.boundary_loops;
        for (rgb::HalfedgeId h = start; h.valid() && !visited[h.idx]; h = boundary_out[mesh.to_vertex(h).idx]) visited[h.idx] = 1;
    }
    return s;
}

void print_summary(std::ostream& out, const MeshSummary& s) {
    out << "vertices: " << s.vertices << "\nedges: " << s.edges << "\nfaces: " << s.faces << "\nboundary loops: " << s.boundary_loops
        << "\nEuler characteristic: " << s.euler_characteristic << "\ntriangles per colour: green " << s.green << ", red " << s.red
        << ", blue " << s.blue << "\ntriangles per level:";
    for (const auto& [level, count] : s.faces_per_level) out << ' ' << level << ':' << count;
    out << '\n';
}

void print_quality(std::ostream& out, const rgb::Mesh& mesh) {
    out << "triangle quality per level (angles in degrees; aspect ratio: longest edge x perimeter / (4 sqrt(3) x area), 1 when "
           "equilateral):\n";
    for (const auto& [level, q] : rgb::quality_by_level(mesh))
        out << "  level " << level << ": minimum angle " << q.min_angle << ", mean minimum angle " << q.mean_min_angle
            << ", worst aspect ratio " << q.max_aspect_ratio << '\n';
}

}  // namespace cli
