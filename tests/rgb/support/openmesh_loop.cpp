#include "support/openmesh_loop.h"

#include <stdexcept>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

namespace rgbtest {
namespace {

// LoopT casts points to the Normal type while summing, so both must be double.
struct DoubleTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using OpenMeshTriangles = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

}  // namespace

TestMesh openmesh_loop(const TestMesh& base, int k) {
    OpenMeshTriangles om;
    std::vector<OpenMeshTriangles::VertexHandle> handles;
    for (const glm::dvec3& p : base.positions) handles.push_back(om.add_vertex(OpenMesh::Vec3d(p.x, p.y, p.z)));
    for (const rgb::Triangle& t : base.triangles)
        if (!om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
            throw std::runtime_error("OpenMesh rejected a face of " + base.name);
    OpenMesh::Subdivider::Uniform::LoopT<OpenMeshTriangles, double> loop;
    loop.attach(om);
    loop(static_cast<std::size_t>(k));
    loop.detach();

    TestMesh result{base.name + " (OpenMesh LoopT)", {}, {}};
    for (auto v : om.vertices()) {
        const OpenMesh::Vec3d& p = om.point(v);
        result.positions.push_back({p[0], p[1], p[2]});
    }
    for (auto f : om.faces()) {
        rgb::Triangle t;
        int i = 0;
        for (auto v : om.fv_range(f)) t[i++] = static_cast<std::uint32_t>(v.idx());
        result.triangles.push_back(t);
    }
    return result;
}

}  // namespace rgbtest
