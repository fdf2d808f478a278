#pragma once
// Small meshes built in code for the renderer tests.
#include "rgb/mesh/mesh.h"

namespace render_test {

// A unit icosahedron subdivided `subdivisions` times by edge midpoints pushed onto the unit sphere,
// then scaled by `scale`.
rgb::Mesh icosphere(int subdivisions, double scale = 1.0);
// A cage with detail (rgb/mesh/detail_positions.h): the base mesh of icosphere(subdivisions), with
// the points of its hierarchy up to `detail_level` on a bumpy sphere, bumpy_sphere_point of each
// point's base-space position.
rgb::Mesh bumpy_cage(int subdivisions, int detail_level);
// The bumpy sphere's point in the direction of p: radius 1 plus a wave of amplitude 0.04.
glm::dvec3 bumpy_sphere_point(const glm::dvec3& p);
// Live face f's largest distance to the detail's dense surface, found independently of the core's
// measure (rgb/values/surface_error.h): every vertex of Σ(l+2) (l its level) of f's base face whose
// base-space position lies in f, its detail point against the point at the same barycentric
// coordinates of the flat triangle between f's displayed corners.
double brute_force_detail_distance(const rgb::Mesh& mesh, rgb::FaceId f);
// An n x n grid of quads (two triangles each) covering [-1, 1]^2 in the plane y = 0, facing +y.
rgb::Mesh grid(int n);

}  // namespace render_test
