#pragma once
// Layer rgb/lod (requests, dabs, refinement, the LOD driver, criteria, view-dependent LOD: what to
// refine, in a canonical order): includes every core layer. docs/architecture.md draws the layers.
// Level-of-detail requests, and the engine that carries them out (spec §3.5; docs/requests.md,
// "What a request means" states the contract these functions keep).
//
// A request names a level N and a region in base space (a ball, or the whole surface, optionally
// only inside some base faces). A triangle T of some Σj meets the region when its base-space
// triangle meets the ball. Then:
//   - Refine asks for the three edge midpoints of every Σj triangle (j < N) that meets the region;
//     the result holds them and exactly what the RGB topology needs besides (their closure).
//   - Coarsen removes every vertex of level > N that lies on an edge of a Σj triangle (j >= N)
//     meeting the region, and every vertex that cannot exist without one of them.
//   - Set does both: afterwards every face meeting the region has level exactly N.
// The result is a function of the current vertex set and the request alone, triangulated in the
// normal form of spec §3.5, so requests of one kind commute, and order, storage and history do not
// change the mesh.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

enum class RequestKind { Set, Refine, Coarsen };

// A further ball around the request's centre with a level of its own (a brush's falloff).
struct LevelBand {
    int level = 0;
    double radius = 0.0;
};

struct LevelRequest {
    RequestKind kind = RequestKind::Set;
    int level = 0;
    std::optional<Sphere> sphere;  // none: the whole surface
    // Refine and Coarsen only: a triangle meeting several of these balls (and the sphere) takes the
    // finest (Refine) or coarsest (Coarsen) of their levels. Equivalent to one request per ball.
    std::vector<LevelBand> taper;
    // When not empty (sorted ids), only triangles inside these base faces count.
    std::vector<std::uint32_t> base_faces;
};

struct RequestStats {
    std::size_t splits = 0;
    std::size_t removals = 0;
    bool level_cap_bound = false;  // wanted detail was left out at the maximum level
    RequestStats& operator+=(const RequestStats& o) {
        splits += o.splits;
        removals += o.removals;
        level_cap_bound = level_cap_bound || o.level_cap_bound;
        return *this;
    }
};

// Throws std::invalid_argument for a level outside 0..kMaxLevel or a non-positive or non-finite
// radius. Costs in proportion to the faces in and around the region, never to the mesh.
RequestStats apply_request(Mesh& mesh, const LevelRequest& request);

// The live faces whose parent triangles (the triangles of Σl they are pieces of) meet the ball, found
// the way requests find their region: in proportion to the faces in and around it.
std::vector<FaceId> faces_meeting(const Mesh& mesh, const Sphere& sphere);

// An upper estimate of the number of triangles the mesh will have after the request, from the base
// faces the region meets (4^N triangles per base face, scaled by the part of it the ball can
// cover), so that callers can refuse a request before it exhausts memory.
double estimated_triangles(const Mesh& mesh, const LevelRequest& request);

}  // namespace rgb
