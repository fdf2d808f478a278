// The baseline of the whole-process benchmarks: the same job as `rgbsub refine IN -o OUT --level N`
// done with OpenMesh: read the OBJ, build the mesh, LoopT N steps, write an OBJ with 17 significant
// digits. Prints the in-process time of build + LoopT + extraction into plain arrays, per new vertex,
// for the engine comparison. Usage: openmesh_refine IN.obj OUT.obj N
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

namespace {

// LoopT sums points in the Normal type, so both are double.
struct DoubleTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using Triangles = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using Clock = std::chrono::steady_clock;

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: openmesh_refine IN.obj OUT.obj N\n");
        return 1;
    }
    Triangles read;
    if (!OpenMesh::IO::read_mesh(read, argv[1])) {
        std::fprintf(stderr, "openmesh_refine: cannot read %s\n", argv[1]);
        return 2;
    }
    // The engine part, like rgbsub's: plain arrays in, plain arrays out.
    std::vector<double> positions;
    std::vector<int> faces;
    for (auto v : read.vertices())
        for (int i = 0; i < 3; ++i) positions.push_back(read.point(v)[i]);
    for (auto f : read.faces())
        for (auto v : read.fv_range(f)) faces.push_back(v.idx());
    const auto start = Clock::now();
    Triangles mesh;
    std::vector<Triangles::VertexHandle> handles;
    for (std::size_t i = 0; i < positions.size(); i += 3)
        handles.push_back(mesh.add_vertex(OpenMesh::Vec3d(positions[i], positions[i + 1], positions[i + 2])));
    for (std::size_t i = 0; i < faces.size(); i += 3) mesh.add_face(handles[faces[i]], handles[faces[i + 1]], handles[faces[i + 2]]);
    const std::size_t base_vertices = mesh.n_vertices();
    OpenMesh::Subdivider::Uniform::LoopT<Triangles, double> loop;
    loop.attach(mesh);
    loop(static_cast<std::size_t>(std::atoi(argv[3])));
    loop.detach();
    std::vector<double> out_positions;
    std::vector<int> out_faces;
    out_positions.reserve(3 * mesh.n_vertices());
    out_faces.reserve(3 * mesh.n_faces());
    for (auto v : mesh.vertices())
        for (int i = 0; i < 3; ++i) out_positions.push_back(mesh.point(v)[i]);
    for (auto f : mesh.faces())
        for (auto v : mesh.fv_range(f)) out_faces.push_back(v.idx());
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    const std::size_t added = mesh.n_vertices() - base_vertices;
    std::printf("openmesh: %.1f ms in process (build + LoopT + extraction), %zu new vertices, %.1f ns per new vertex\n", ms,
                added, 1e6 * ms / static_cast<double>(added));
    if (!OpenMesh::IO::write_mesh(mesh, argv[2], OpenMesh::IO::Options::Default, 17)) {
        std::fprintf(stderr, "openmesh_refine: cannot write %s\n", argv[2]);
        return 3;
    }
    return 0;
}
