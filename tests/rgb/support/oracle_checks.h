#pragma once
// Assertions comparing an RGB mesh with the uniform Loop oracle and with its base mesh, returning
// gtest AssertionResults that say which vertex or face differs and how.
#include <gtest/gtest.h>

#include "rgb/mesh/mesh.h"
#include "support/identity_tracker.h"
#include "support/test_meshes.h"

namespace rgbtest {

struct OracleView {
    const rgb::Mesh& mesh;
    const IdentityTracker& ids;
    double tolerance;  // absolute: 1e-12 times the base bounding-box diagonal
};

double oracle_tolerance(const TestMesh& base);

// check_invariants(mesh), with its report as the failure message.
testing::AssertionResult invariants_hold(const rgb::Mesh& mesh);
// The insertion position equals the oracle at the vertex's own level, and the displayed position the
// oracle at the display level.
testing::AssertionResult vertex_agrees(const OracleView& view, rgb::VertexId v);
// A green G_l is a face of the oracle's Σl, orientation included (other colours pass).
testing::AssertionResult face_agrees(const OracleView& view, rgb::FaceId f);
// vertex_agrees and face_agrees for everything live.
testing::AssertionResult everything_agrees(const OracleView& view);
// The mesh is Σk: the same identities, every face green of level k and equal to the oracle's faces
// (orientation included), every vertex displayed at level k at the oracle's position.
testing::AssertionResult equals_uniform(const OracleView& view, int k);
// The mesh is its base mesh bit for bit: same vertex slots and positions (==), the same faces up to
// rotation, every face green of level 0.
testing::AssertionResult equals_base(const rgb::Mesh& mesh, const TestMesh& base);

}  // namespace rgbtest
