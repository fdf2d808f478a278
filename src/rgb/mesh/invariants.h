#pragma once
// Checks the global invariants of an RGB triangulation (spec §1.6) and reports each violation.
#include <string>
#include <vector>

namespace rgb {

class Mesh;

struct InvariantReport {
    std::vector<std::string> violations;  // one readable line per violation, naming faces/vertices
    bool ok() const { return violations.empty(); }
};

// What a caller has established already and need not be checked again.
struct KnownInvariants {
    // Every face is in its place in the hierarchy: restore_state gives each face the type whose place
    // its corners fit, by the very test check_invariants would repeat (face_location.h).
    bool hierarchy_place = false;
};

// Edge agreement from both sides, vertex levels per face type, each face in its place in the
// hierarchy (its corners' addresses), angle sums, manifold adjacency and orientation, no two blues of
// one level sharing a red edge, counts of live slots.
InvariantReport check_invariants(const Mesh& mesh, std::size_t max_reports = 50, KnownInvariants known = {});
// The normal form of spec §3.5 that the requests and remove_vertex keep (single swaps may break it).
InvariantReport check_normal_form(const Mesh& mesh, std::size_t max_reports = 50);

}  // namespace rgb
