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

struct OpenMeshLoop::Impl {
    std::string name;
    OpenMeshTriangles mesh;
};

OpenMeshLoop::OpenMeshLoop(const TestMesh& base) : impl_(std::make_unique<Impl>()) {
    impl_->name = base.name;
    OpenMeshTriangles& om = impl_->mesh;
    std::vector<OpenMeshTriangles::VertexHandle> handles;
    for (const glm::dvec3& p : base.positions) handles.push_back(om.add_vertex(OpenMesh::Vec3d(p.x, p.y, p.z)));
    for (const rgb::Triangle& t : base.triangles)
        if (!om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
            throw std::runtime_error("OpenMesh rejected a face of " + base.name);
}

OpenMeshLoop::~OpenMeshLoop() = default;

void OpenMeshLoop::subdivide(int k) {
    OpenMesh::Subdivider::Uniform::LoopT<OpenMeshTriangles, double> loop;
    loop.attach(impl_->mesh);
    loop(static_cast<std::size_t>(k));
    loop.detach();
}

std::size_t OpenMeshLoop::num_faces() const { return impl_->mesh.n_faces(); }

TestMesh OpenMeshLoop::result() const {
    const OpenMeshTriangles& om = impl_->mesh;
    TestMesh result{impl_->name + " (OpenMesh LoopT)", {}, {}};
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

TestMesh openmesh_loop(const TestMesh& base, int k) {
    OpenMeshLoop loop(base);
    loop.subdivide(k);
    return loop.result();
}

}  // namespace rgbtest
