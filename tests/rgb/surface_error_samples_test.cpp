// The measure of a displayed surface (rgb/values/surface_error.h) against a plain evaluation of its
// definition: for each live face in slot order, the 15 points of Σ(l+2) of the triangle of Σl it is a
// piece of (parent_triangle), those inside the face, their barycentric weights as quotients of
// lattice areas, the flat face's point there (interpolate) against the evaluator's limit point; the
// largest distance, kept at the first face in slot order and its first sample where tied. The
// measure takes shortcuts (a face's lattice from its corners' addresses, weights by a reciprocal,
// square roots only for a new largest square), so its bits must be the definition's: on faces of
// mixed levels (red and green) with corners on base edges and at base vertices, and on a tie between
// faces.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "rgb/lod/requests.h"
#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/hierarchy_triangle.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/surface_error.h"
#include "support/set_level.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

using Numerators = std::array<std::uint32_t, 3>;

// The definition, face by face: corners shown at `shown` (by vertex slot).
rgb::SurfaceError definition_error(const rgb::Mesh& mesh, rgb::FaceId f, const std::vector<glm::dvec3>& shown) {
    const rgb::BaseMesh& base = mesh.base();
    rgb::HierarchyEvaluator evaluator(base);
    const int level = mesh.level(f);
    const std::uint32_t g = rgb::base_face_of(mesh, f);
    std::array<Numerators, 3> corners;
    std::array<glm::dvec3, 3> at;
    for (std::size_t c = 0; c < 3; ++c) {
        const rgb::VertexId v = mesh.face_vertices(f)[c];
        corners[c] = rgb::numerators_at(*rgb::in_face(base, mesh.address(v), g), level + 2);
        at[c] = shown[v.idx];
    }
    const std::array<rgb::SurfacePoint, 3> parent = rgb::parent_triangle(mesh, f, g);
    const std::int64_t area = rgb::lattice_orientation(corners[0], corners[1], corners[2]);
    rgb::SurfaceError out;
    for (const rgb::SampleWeights& w : rgb::sample_weights()) {
        Numerators q{};
        for (std::size_t c = 0; c < 3; ++c)
            for (std::size_t i = 0; i < 3; ++i)
                q[i] += static_cast<std::uint32_t>(w[c]) * rgb::numerators_at(parent[c], level)[i];
        const std::int64_t w0 = rgb::lattice_orientation(q, corners[1], corners[2]);
        const std::int64_t w1 = rgb::lattice_orientation(corners[0], q, corners[2]);
        const std::int64_t w2 = rgb::lattice_orientation(corners[0], corners[1], q);
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const glm::dvec3 limit = evaluator.limit_position(rgb::reduced(rgb::SurfacePoint{g, q, level + 2}));
        const glm::dvec3 flat = rgb::interpolate(at, {double(w0) / double(area), double(w1) / double(area), double(w2) / double(area)});
        const double error = glm::distance(flat, limit);
        ++out.samples;
        if (error > out.max_error) {
            out.max_error = error;
            out.where = limit;
        }
    }
    return out;
}

struct Worst {
    rgb::SurfaceError error;
    std::size_t faces_at_max = 0;  // faces whose own largest error is the largest
};

Worst definition_error(const rgb::Mesh& mesh, const std::vector<glm::dvec3>& shown) {
    Worst out;
    for (rgb::FaceId f : mesh.faces()) {
        const rgb::SurfaceError e = definition_error(mesh, f, shown);
        out.error.samples += e.samples;
        if (e.max_error > out.error.max_error) {
            out.error.max_error = e.max_error;
            out.error.where = e.where;
            out.faces_at_max = 0;
        }
        if (e.max_error == out.error.max_error) ++out.faces_at_max;
    }
    return out;
}

void expect_same(const rgb::SurfaceError& measured, const rgb::SurfaceError& defined) {
    EXPECT_EQ(measured.max_error, defined.max_error);
    EXPECT_EQ(measured.where, defined.where);
    EXPECT_EQ(measured.samples, defined.samples);
}

// An octahedron around the origin refined to level 3 in a ball at one corner and to level 1 elsewhere:
// faces of levels 1 to 3, green ones between them.
rgb::Mesh mixed_octahedron() {
    rgb::Mesh mesh = make_rgb_mesh(octahedron());
    set_level(mesh, 1);
    set_level(mesh, 3, rgb::Sphere{glm::dvec3(1.0, 0.0, 0.0), 0.6});
    return mesh;
}

TEST(SurfaceErrorSamples, AreTheDefinitionsOnFacesOfMixedLevels) {
    const rgb::Mesh mesh = mixed_octahedron();
    int lowest = 99, highest = 0;
    for (rgb::FaceId f : mesh.faces()) {
        lowest = std::min(lowest, mesh.level(f));
        highest = std::max(highest, mesh.level(f));
    }
    ASSERT_EQ(lowest, 1);
    ASSERT_EQ(highest, 3);
    // The displayed surface (face_surface_error, face by face), and the written limit positions.
    std::vector<glm::dvec3> displayed(mesh.vertex_capacity()), limits(mesh.vertex_capacity());
    rgb::HierarchyEvaluator evaluator(mesh.base());
    for (rgb::VertexId v : mesh.vertices()) {
        displayed[v.idx] = rgb::displayed_position(mesh, v);
        limits[v.idx] = evaluator.limit_position(mesh.address(v));
    }
    for (rgb::FaceId f : mesh.faces()) {
        SCOPED_TRACE("face " + std::to_string(f.idx));
        expect_same(rgb::face_surface_error(mesh, evaluator, f), definition_error(mesh, f, displayed));
    }
    expect_same(rgb::displayed_surface_error(mesh), definition_error(mesh, displayed).error);
    expect_same(rgb::surface_error_at(mesh, limits), definition_error(mesh, limits).error);
}

TEST(SurfaceErrorSamples, BreakATieAtTheFirstFace) {
    // Every corner shown at the centre: the error at a sample is its limit point's distance from the
    // centre. On the mixed octahedron the largest is met at a sample on an edge between two faces,
    // the same bits from both (the third corner's weight is zero): the first face in slot order
    // gives it. Measured with a uniform level 2 beside it, as an LOD set measures its levels together.
    const rgb::Mesh mixed = mixed_octahedron();
    rgb::Mesh uniform = make_rgb_mesh(octahedron());
    set_level(uniform, 2);
    const std::vector<glm::dvec3> centre_mixed(mixed.vertex_capacity(), glm::dvec3(0.0));
    const std::vector<glm::dvec3> centre_uniform(uniform.vertex_capacity(), glm::dvec3(0.0));
    const Worst mixed_defined = definition_error(mixed, centre_mixed), uniform_defined = definition_error(uniform, centre_uniform);
    EXPECT_GE(mixed_defined.faces_at_max, 2u);
    const rgb::Mesh* const meshes[] = {&mixed, &uniform};
    const std::vector<glm::dvec3> corners[] = {centre_mixed, centre_uniform};
    const std::vector<rgb::SurfaceError> errors = rgb::surface_errors_at(meshes, corners);
    ASSERT_EQ(errors.size(), 2u);
    expect_same(errors[0], mixed_defined.error);
    expect_same(errors[1], uniform_defined.error);
}

}  // namespace
}  // namespace rgbtest
