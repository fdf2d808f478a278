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
// in arrays indexed by the point's numerators.
//
// A point strictly inside an untagged interior base edge is such a vertex too, and so are the points
// of the neighbouring face across it: the grid computes those the same way (the "diamond" of the two
// faces), keeping the neighbour's points in a band along the edge. Only their insertion positions are
// ever needed there, and only of the points one step of their own level away from the edge (the
// edge points' stencils and rings, and those points' stencils, reach no further), so the band holds
// 2^(m+1) points of each level m. The evaluator answers for the rest: base vertices, points on
// boundary or tagged base edges, and the neighbour's points on its other edges.
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
    // Computes the values of every point of the started face at once, level by level over arrays,
    // for a caller that will ask for (nearly) all of them: a few times cheaper than asking for them
    // one by one, which recurses through each point's stencil and ring. The same values. Two arrays
    // of one level's values beside the slots: 12 MB more at kMaxLevel.
    void fill();
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
    // keeps its insertion position and limit (the diamond's, or on a boundary edge the evaluator's)
    // and gives its values at finer levels by the closed form, as the evaluator does; a base vertex
    // or tagged point asks the evaluator for each level.
    glm::dvec3 boundary_value(const Point& p, int k);
    glm::dvec3 evaluators_value(const Point& p, int k);
    // The point of base edge `edge` (the one opposite that corner) whose next corner's numerator is t.
    Point on_edge(int edge, std::uint32_t t) const;
    // An untagged interior edge's point at numerator t of its own level: Loop's rules over the two
    // faces (its limit from its insertion position).
    glm::dvec3 diamond_insertion(int edge, std::uint32_t t, int level);
    glm::dvec3 diamond_limit(int edge, std::uint32_t t, int level, const glm::dvec3& insertion);
    // The insertion position of the neighbour's point across `edge` at `level` one step from the
    // edge, `b` steps from the edge's next corner.
    glm::dvec3 band_insertion(int edge, int level, std::uint32_t b);

    const BaseMesh& base_;
    HierarchyEvaluator& evaluator_;
    std::uint32_t face_ = 0;
    int level_ = 0;
    std::size_t stride_ = 1;
    std::uint32_t stamp_ = 0;  // the slots written since the last start hold it
    std::vector<Slot> slots_;
    // How the started face's edges' points are computed, and across an interior edge the neighbour
    // and its corners at the edge's next and previous corners and opposite it.
    enum class EdgeRule : std::uint8_t { kDiamond, kBoundary, kTagged };
    struct Edge {
        EdgeRule rule = EdgeRule::kTagged;
        std::uint32_t neighbour = 0;
        std::array<std::uint8_t, 3> corners{};
        double gamma = 0.0;
    };
    std::array<Edge, 3> edges_;
    // Points on the boundary by edge (the first zero numerator) and position along it (the next
    // numerator); the evaluator's values by that and level.
    struct EdgeSlot {
        glm::dvec3 insertion{0.0}, limit{0.0};
        std::uint32_t stamp = 0, limit_stamp = 0;
    };
    std::vector<EdgeSlot> edge_slots_;
    std::vector<glm::dvec3> evaluated_;
    std::vector<std::uint32_t> evaluated_stamps_;
    // The neighbours' bands: by edge, then 2^m + b for the point of level m b steps along.
    struct BandSlot {
        glm::dvec3 insertion{0.0};
        std::uint32_t stamp = 0;
    };
    std::vector<BandSlot> band_;
    // fill()'s values of every point at the level before and at the level it computes.
    std::array<std::vector<glm::dvec3>, 2> fill_values_;
};

}  // namespace rgb
