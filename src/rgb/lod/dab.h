#pragma once
// A brush dab as requests (spec §3.4, §3.5): the editor's brush and `rgbsub apply`'s `dab` lines go
// through here, so a recorded stroke replays to the identical mesh. Everything is in base space.
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/lod/requests.h"

namespace rgb {

class Mesh;

enum class BrushMode { Refine, Coarsen, Set };

struct Dab {
    BrushMode mode = BrushMode::Refine;
    int level = 0;
    double radius = 0.0;   // base space
    double falloff = 0.0;  // fraction of the radius, from the rim inwards, over which the level tapers
    glm::dvec3 centre{0.0};
    // The direction the camera looks along: only base faces facing it (against it) and connected to
    // the face nearest the centre through such faces within the ball are painted. None: no test.
    std::optional<glm::dvec3> view;
};

// The level a dab asks for at distance d from its centre, or -1 (none): refine tapers from the level
// at the core to 0 at the rim, coarsen from the level at the core to kMaxLevel (removing nothing) at
// the rim, set holds the level over the core and leaves the falloff band alone.
int dab_level_at(BrushMode mode, int level, double falloff, double d, double radius);

// The requests a dab amounts to (one, with a taper for the falloff).
LevelRequest dab_request(const Mesh& mesh, const Dab& dab);
RequestStats apply_dab(Mesh& mesh, const Dab& dab);

// Base faces the dab may paint with its view test: those meeting the ball that face the viewer and are
// connected, through such faces, to the base face nearest the centre. Sorted.
std::vector<std::uint32_t> facing_base_faces(const Mesh& mesh, const Sphere& ball, const glm::dvec3& view);

}  // namespace rgb
