#pragma once
// Finding what the brush touches on the displayed surface (spec §3.4): the front-facing triangle a
// ray hits first, and the triangles within a sphere, grown through face adjacency from a hit face so
// that the cost follows the footprint, not the mesh. Reads the positions of a
// render::SurfaceGeometry (face slot f = vertices 3f..3f+2), which the observer keeps current.
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "app/view_camera.h"
#include "rgb/handles.h"

namespace rgb {
class Mesh;
}
namespace render {
class SurfaceGeometry;
}

namespace app {

struct SurfaceHit {
    rgb::FaceId face;
    glm::dvec3 point{0.0};
    double distance = 0.0;  // along the ray
};

// The nearest front-facing triangle along the ray, testing every live face slot.
std::optional<SurfaceHit> pick_surface(const render::SurfaceGeometry& geometry, const Ray& ray);

// The same among the triangles within `reach` of `near` that are connected to `seed` through such
// triangles: what a stroke tests between two samples, growing from the previous hit.
std::optional<SurfaceHit> pick_surface_near(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                            const Ray& ray, rgb::FaceId seed, const glm::dvec3& near, double reach);

// Live faces that come within `radius` of `centre` and are connected to `seed` through such faces
// (seed first).
std::vector<rgb::FaceId> faces_in_sphere(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                         rgb::FaceId seed, const glm::dvec3& centre, double radius);

}  // namespace app
