#pragma once
// Exact normals of the Loop limit surface at the vertices of an adaptive mesh, from the limit
// tangent masks applied to each vertex's ring in the uniform mesh of its own level (spec §4.4: the
// ring's control points come from the mesh where it holds them, else from the hierarchy evaluator,
// with the same bits either way). The masks and their derivation are in limit_normals.cpp.
//
// Smooth rules only: when crease and corner tags reach the core, tagged vertices need the crease
// and corner tangent masks (a follow-up).
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"
#include "rgb/mesh/surface_point.h"

namespace rgb {

class BaseMesh;
class HierarchyEvaluator;
class Mesh;

// The unit normal of the limit surface at hierarchy vertex p, oriented like the base faces.
glm::dvec3 limit_normal(const BaseMesh& base, HierarchyEvaluator& evaluator, const SurfacePoint& p);

// The same for every live vertex of `mesh`, by vertex slot (dead slots: zero). Does not touch the
// mesh's limit cache.
std::vector<glm::dvec3> limit_normals(const Mesh& mesh);

// The ring of hierarchy vertex p (level >= 1) in the uniform mesh of its level, counter-clockwise
// around the base faces' normal: six points inside the surface; four on the boundary, the first and
// last the two along the boundary. (A base vertex's ring is BaseMesh::ring, in the same order.)
std::vector<SurfacePoint> ordered_ring(const BaseMesh& base, const SurfacePoint& p);

}  // namespace rgb
