#pragma once
// Limit points of many vertices inside one base face, as HierarchyEvaluator gives them, bit for bit,
// at a few array reads each instead of its address arithmetic and hash tables: the measure of an LOD
// set (surface_error.h) asks for about eight new limit points per face of its finest level, which
// through the evaluator alone cost several times making and writing the level.
//
// A point strictly inside the base face (no zero barycentric numerator) is a regular interior vertex
// whatever the base mesh's tags (vertex_rules.h: tags live on base edges and vertices), so its
// insertion position is Loop's interior edge rule over its four stencil points, its limit the
// valence-6 mask over its six neighbours, and its value at a finer level the closed form between the
// two: the formulas of loop_rules.h that the evaluator applies, on the same values (the edge rule and
// the limit mask do not depend on the order of their points), so the same bits. Those values are kept
// in arrays indexed by the point's numerators. Every point on the base face's boundary (its edges and
// corners, where base faces meet, tags apply and the base mesh's valences show) is the evaluator's.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"

namespace rgb {

class BaseMesh;
class HierarchyEvaluator;

class FaceGridLimits {
public:
    // The deepest level a grid covers: (2^9 + 1)^2 slots, 15 MB; deeper points are the evaluator's.
    static constexpr int kMaxLevel = 9;

    // `evaluator` is over `base` and answers for the points on the face's boundary.
    FaceGridLimits(const BaseMesh& base, HierarchyEvaluator& evaluator) : base_(base), evaluator_(evaluator) {}

    // Starts on base face `face` for points up to `level` (at most kMaxLevel), forgetting the values
    // of the face before.
    void start(std::uint32_t face, int level);
    // p^inf of a point of the started face at a level up to the started one (reduced or not).
    glm::dvec3 limit_position(const SurfacePoint& p);
    // p^k of a point of the started face at a level up to the started one, for k from its level to
    // kMaxLevel (so at its level its insertion position), as HierarchyEvaluator::control_point.
    glm::dvec3 control_point(const SurfacePoint& p, int k);
    std::uint32_t face() const { return face_; }
    int level() const { return level_; }

private:
    // A point as numerators (a0, a1, a2) over 2^level_ (any reducible form).
    using Point = std::array<std::uint32_t, 3>;
    struct Slot {
        glm::dvec3 insertion{0.0}, limit{0.0};
        std::uint32_t insertion_stamp = 0, limit_stamp = 0;
    };
    int level_of(const Point& p) const;
    std::size_t slot(const Point& p) const { return std::size_t(p[1]) * stride_ + p[2]; }
    SurfacePoint surface_point(const Point& p) const;
    static bool inside(const Point& p) { return p[0] != 0 && p[1] != 0 && p[2] != 0; }
    glm::dvec3 insertion(const Point& p, int level);
    glm::dvec3 limit(const Point& p, int level);
    glm::dvec3 control_point(const Point& p, int k);
    // The value of a point on the face's boundary at level k (kMaxLevel + 1: its limit), kept: the
    // points inside next to the boundary ask for each several times. A point on an untagged base edge
    // keeps its insertion position and limit from the evaluator and gives its values at finer levels
    // by the closed form, as the evaluator does; a base vertex or tagged point asks the evaluator for
    // each level.
    glm::dvec3 boundary_value(const Point& p, int k);
    glm::dvec3 evaluators_value(const Point& p, int k);

    const BaseMesh& base_;
    HierarchyEvaluator& evaluator_;
    std::uint32_t face_ = 0;
    int level_ = 0;
    std::size_t stride_ = 1;
    std::uint32_t stamp_ = 0;  // the slots written since the last start hold it
    std::vector<Slot> slots_;
    // Points on the boundary by edge (the first zero numerator) and position along it (the next
    // numerator); the evaluator's values by that and level.
    struct EdgeSlot {
        glm::dvec3 insertion{0.0}, limit{0.0};
        double gamma = 0.0;
        std::uint32_t stamp = 0, limit_stamp = 0;
        bool tagged = false;
    };
    std::vector<EdgeSlot> edge_slots_;
    std::vector<glm::dvec3> evaluated_;
    std::vector<std::uint32_t> evaluated_stamps_;
};

}  // namespace rgb
