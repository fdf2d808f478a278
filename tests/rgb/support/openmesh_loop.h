#pragma once
// Uniform Loop subdivision by OpenMesh's LoopT (original weights, like the spec), in double precision,
// as an external reference for refine_uniform and the baseline of the core benchmark.
#include <memory>

#include "support/test_meshes.h"

namespace rgbtest {

// An OpenMesh copy of a mesh, subdivided in place; split from the conversions so that a benchmark
// can time the subdivision alone.
class OpenMeshLoop {
public:
    explicit OpenMeshLoop(const TestMesh& base);
    ~OpenMeshLoop();
    OpenMeshLoop(const OpenMeshLoop&) = delete;
    OpenMeshLoop& operator=(const OpenMeshLoop&) = delete;

    // k steps of OpenMesh::Subdivider::Uniform::LoopT.
    void subdivide(int k);
    std::size_t num_faces() const;
    TestMesh result() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The base mesh after k steps of LoopT.
TestMesh openmesh_loop(const TestMesh& base, int k);

}  // namespace rgbtest
