#include "rgb/values/hierarchy_positions.h"

#include <array>
#include <atomic>
#include <memory>
#include <stdexcept>

#include "rgb/mesh/address_index.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/support/parallel.h"
#include "rgb/values/hierarchy_evaluator.h"

namespace rgb {

namespace {

// Vertices ordered by level (what a vertex's values need is coarser), and within a level by base face
// (its neighbours' table entries are then in cache), each (level, face) in vertex order.
std::vector<std::uint32_t> level_then_face_order(std::span<const SurfacePoint> points, std::size_t base_faces) {
    // Stable counting sorts (this runs on one thread while the others wait).
    auto counting_sort = [&](std::size_t count, std::size_t buckets, auto vertex, auto key) {
        std::vector<std::uint32_t> start(buckets + 1, 0), out(count);
        for (std::size_t i = 0; i < count; ++i) ++start[key(vertex(i)) + 1];
        for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
        for (std::size_t i = 0; i < count; ++i) out[start[key(vertex(i))]++] = vertex(i);
        return out;
    };
    int top = 0;
    for (const SurfacePoint& p : points) top = std::max(top, p.level);
    const auto levels = static_cast<std::size_t>(top) + 1;
    const auto vertex_itself = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
    // One sort by (level, face) where a bucket per pair costs less than the vertices do.
    if (levels * base_faces <= points.size())
        return counting_sort(points.size(), levels * base_faces, vertex_itself, [&](std::uint32_t v) {
            return static_cast<std::uint32_t>(static_cast<std::size_t>(points[v].level) * base_faces + points[v].face);
        });
    // Else by face, then by level.
    const auto by_face = counting_sort(points.size(), base_faces, vertex_itself, [&](std::uint32_t v) { return points[v].face; });
    return counting_sort(points.size(), levels, [&](std::size_t i) { return by_face[i]; },
                         [&](std::uint32_t v) { return std::uint32_t(points[v].level); });
}

// Vertices of one level need only coarser values, so each level is computed in parallel. A limit is
// computed by whichever thread needs it first; one that finds it unclaimed stores it (claim with an
// atomic flag, publish with a second state), others compute their own copy, which has the same bits.
// C sets of values at once (bases[c]'s positions; all have the same faces and tags): the lookups of
// stencils and rings, the costly part, are shared, each value has the bits it has alone.
template <std::size_t C>
class Evaluation {
public:
    using Values = std::array<glm::dvec3, C>;

    Evaluation(std::array<const BaseMesh*, C> bases, std::span<const SurfacePoint> points, const AddressIndex& index)
        : bases_(bases), base_(*bases[0]), points_(points), index_(index),
          limit_(new Values[points.size()]), limit_state_(new std::atomic<std::uint8_t>[points.size()]()),
          blocks_(parallel_blocks(points.size(), 1 << 14)) {
        if (base_.has_sharp_features()) {
            tagged_.resize(points.size());
            for (std::size_t v = 0; v < points.size(); ++v) tagged_[v] = !follows_untagged_rules(base_, points[v]);
        }
        base_gamma_.resize(base_.num_vertices());
        for (std::uint32_t v = 0; v < base_.num_vertices(); ++v) base_gamma_[v] = loop_gamma(base_.valence(v), base_.is_boundary_vertex(v));
        for (std::size_t b = 0; b < blocks_; ++b)
            for (std::size_t c = 0; c < C; ++c) evaluators_.emplace_back(*bases[c]);
        for (std::vector<glm::dvec3>& values : insertion_) values.resize(points.size());
    }

    // Every vertex's insertion value, coarsest level first; gives the order used.
    std::vector<std::uint32_t> insert_all() {
        for (std::uint32_t v = 0; v < base_.num_vertices(); ++v)
            for (std::size_t c = 0; c < C; ++c) insertion_[c][v] = bases_[c]->position(v);
        std::vector<std::uint32_t> order = level_then_face_order(points_, base_.num_faces());
        for (std::size_t begin = 0, end; begin < order.size(); begin = end) {
            end = begin;
            while (end < order.size() && points_[order[end]].level == points_[order[begin]].level) ++end;
            if (points_[order[begin]].level > 0)
                in_parallel(std::span<const std::uint32_t>(order).subspan(begin, end - begin),
                            [&](std::uint32_t v, std::size_t block) {
                                const Values value = insertion_position(points_[v], block);
                                for (std::size_t c = 0; c < C; ++c) insertion_[c][v] = value[c];
                            });
        }
        return order;
    }

    int level(std::uint32_t v) const { return points_[v].level; }

    // f(vertex, block) for each vertex, in blocks_ parallel blocks.
    template <class F>
    void in_parallel(std::span<const std::uint32_t> vertices, const F& f) {
        parallel_blocks_for(vertices.size(), std::min(blocks_, std::max<std::size_t>(vertices.size() >> 12, 1)),
                            [&](std::size_t block, std::size_t begin, std::size_t end) {
                                for (std::size_t i = begin; i < end; ++i) f(vertices[i], block);
                            });
    }

    // p^k(v), k >= level(v), by the closed form of spec §4.2. A vertex whose rules the tags change
    // takes it from the evaluator, as loop_geometry does: the same bits as the operators' mesh.
    Values control_point(std::uint32_t v, int k, std::size_t block) {
        const int l = points_[v].level;
        if (k <= l) return insertion(v);
        Values result;
        if (is_tagged(v)) {
            for (std::size_t c = 0; c < C; ++c) result[c] = evaluator(block, c).control_point(points_[v], k);
            return result;
        }
        const double gamma = v < base_gamma_.size() ? base_gamma_[v] : loop_gamma(6, is_boundary(base_, points_[v]));
        const Values limits = limit(v, block);
        for (std::size_t c = 0; c < C; ++c) result[c] = closed_form(insertion_[c][v], limits[c], gamma, k - l);
        return result;
    }

    // p^inf(v) from its ring at its own level (all coarser or as coarse as v, so known by now). A ring
    // vertex the set lacks (at the edge of a refined region) is computed from the base mesh by the
    // evaluator, which gives the same bits.
    Values limit(std::uint32_t v, std::size_t block) {
        if (limit_state_[v].load(std::memory_order_acquire) == kKnown) return limit_[v];
        const SurfacePoint& p = points_[v];
        const Values centre = insertion(v);
        Values value;
        if (is_tagged(v)) {
            for (std::size_t c = 0; c < C; ++c) value[c] = evaluator(block, c).limit_position(p);
        } else if (p.level == 0) {
            const std::vector<std::uint32_t> ring = base_.ring(v);
            for (std::size_t c = 0; c < C; ++c) {
                if (base_.is_boundary_vertex(v)) {
                    value[c] = boundary_limit(centre[c], insertion_[c][ring.front()], insertion_[c][ring.back()]);
                } else {
                    std::vector<glm::dvec3> around;
                    around.reserve(ring.size());
                    for (std::uint32_t u : ring) around.push_back(insertion_[c][u]);
                    value[c] = interior_limit(centre[c], around);
                }
            }
        } else {
            const auto ring = ring_at_own_level(base_, p);
            const bool boundary = is_boundary(base_, p);
            const std::size_t used = boundary ? 2 : 6;  // a boundary vertex's limit needs its two boundary neighbours
            std::array<std::uint32_t, 6> members;
            bool present = true;
            for (std::size_t r = 0; r < used && present; ++r) {
                members[r] = index_.find(canonical(base_, ring[r]));
                present = members[r] != AddressIndex::kAbsent;
            }
            if (!present) {
                for (std::size_t c = 0; c < C; ++c) value[c] = evaluator(block, c).limit_position(p);
            } else {
                std::array<Values, 6> around;
                for (std::size_t r = 0; r < used; ++r) around[r] = control_point(members[r], p.level, block);
                for (std::size_t c = 0; c < C; ++c) {
                    std::array<glm::dvec3, 6> ring_values;
                    for (std::size_t r = 0; r < used; ++r) ring_values[r] = around[r][c];
                    value[c] = boundary ? boundary_limit(centre[c], ring_values[0], ring_values[1]) : interior_limit(centre[c], ring_values);
                }
            }
        }
        std::uint8_t unclaimed = 0;
        if (limit_state_[v].compare_exchange_strong(unclaimed, kClaimed, std::memory_order_relaxed)) {
            limit_[v] = value;
            limit_state_[v].store(kKnown, std::memory_order_release);
        }
        return value;
    }

    // The limits computed so far, of values set c, by increasing vertex.
    std::vector<HierarchyPositions::Limit> known_limits(std::size_t c) const {
        std::vector<HierarchyPositions::Limit> limits;
        for (std::uint32_t v = 0; v < points_.size(); ++v)
            if (limit_state_[v].load(std::memory_order_relaxed) == kKnown) limits.push_back({v, limit_[v][c]});
        return limits;
    }

    // The insertion values of values set c, given up: the last use of the evaluation's values of c.
    std::vector<glm::dvec3> take_insertions(std::size_t c) { return std::move(insertion_[c]); }

private:
    static constexpr std::uint8_t kClaimed = 1, kKnown = 2;

    // Spec §4.4: the odd rule on the vertex's stencil in Σ(l-1).
    Values insertion_position(const SurfacePoint& p, std::size_t block) {
        const PointStencil st = parent_stencil(base_, p);
        const int l = p.level - 1;
        const Values a = control_point(vertex_at(st.ends[0]), l, block), b = control_point(vertex_at(st.ends[1]), l, block);
        Values result;
        if (st.boundary || (!tagged_.empty() && inserted_at_midpoint(base_, p))) {
            for (std::size_t c = 0; c < C; ++c) result[c] = boundary_edge_point(a[c], b[c]);
            return result;
        }
        const Values d0 = control_point(vertex_at(st.opposite[0]), l, block), d1 = control_point(vertex_at(st.opposite[1]), l, block);
        for (std::size_t c = 0; c < C; ++c) result[c] = interior_edge_point(a[c], b[c], d0[c], d1[c]);
        return result;
    }

    std::uint32_t vertex_at(const SurfacePoint& p) const {
        const std::uint32_t v = index_.find(canonical(base_, p));
        if (v == AddressIndex::kAbsent) throw std::invalid_argument("a vertex's parent triangles are not all present");
        return v;
    }

    HierarchyEvaluator& evaluator(std::size_t block, std::size_t c) { return evaluators_[block * C + c]; }

    bool is_tagged(std::uint32_t v) const { return !tagged_.empty() && tagged_[v]; }

    std::array<const BaseMesh*, C> bases_;
    const BaseMesh& base_;  // bases_[0], for the topology all share
    std::span<const SurfacePoint> points_;
    const AddressIndex& index_;
    std::vector<bool> tagged_;  // per vertex, whether the tags change its rules; empty without tags
    std::vector<double> base_gamma_;
    Values insertion(std::uint32_t v) const {
        Values values;
        for (std::size_t c = 0; c < C; ++c) values[c] = insertion_[c][v];
        return values;
    }

    // Per values set, per vertex: each set is the vector handed over at the end (a copy of the 3M
    // values of a saved 6M-triangle mesh was 72 MB more at the load's peak, copied on one thread).
    std::array<std::vector<glm::dvec3>, C> insertion_;
    // Per vertex, left uninitialised (no pass zero-fills megabytes that are written anyway): a limit
    // is read only once its state says known, so most of limit_'s pages are never touched at all.
    std::unique_ptr<Values[]> limit_;
    std::unique_ptr<std::atomic<std::uint8_t>[]> limit_state_;
    std::size_t blocks_;
    std::vector<HierarchyEvaluator> evaluators_;  // C per block (block * C + c): each caches as it goes
};

// Each vertex's value set c at levels[v] (kLimitLevel: its limit). A value at a level finer than the
// vertex's own needs its limit, and such vertices gather where the order puts them (the coarse
// vertices of a uniformly refined mesh come first): they are cut into blocks of their own, as the
// limits are below, or the first block gets most of the work (loading a saved 1M-triangle file:
// 61 -> 50 ms).
template <std::size_t C>
std::vector<glm::dvec3> values_at(Evaluation<C>& evaluation, std::span<const std::uint32_t> order, std::span<const std::uint8_t> levels,
                                  std::size_t c) {
    std::vector<glm::dvec3> result(levels.size());
    std::vector<std::uint32_t> finer, own;
    for (std::uint32_t v : order) (levels[v] > evaluation.level(v) ? finer : own).push_back(v);
    const auto value = [&](std::uint32_t v, std::size_t block) {
        result[v] = (levels[v] == kLimitLevel ? evaluation.limit(v, block) : evaluation.control_point(v, levels[v], block))[c];
    };
    evaluation.in_parallel(finer, value);
    evaluation.in_parallel(own, value);
    return result;
}

// The positions' part of the pass: insertion values, the values at `levels` (if any), and the limits
// wanted (and any computed on the way).
template <std::size_t C>
HierarchyPositions positions(Evaluation<C>& evaluation, std::span<const std::uint32_t> order, std::span<const std::uint8_t> want_limit,
                             std::span<const std::uint8_t> levels) {
    std::vector<glm::dvec3> at_levels;
    if (!levels.empty()) at_levels = values_at(evaluation, order, levels, 0);
    // Only the vertices whose limit is wanted are cut into blocks: they gather where the order puts
    // them (the base vertices of a uniformly refined mesh all come first), so cutting the whole order
    // would leave one block all the work. Which limits get computed does not depend on the cut.
    std::vector<std::uint32_t> wanted;
    for (std::uint32_t v : order)
        if (want_limit[v]) wanted.push_back(v);
    evaluation.in_parallel(wanted, [&](std::uint32_t v, std::size_t block) { evaluation.limit(v, block); });
    return {evaluation.take_insertions(0), evaluation.known_limits(0), std::move(at_levels)};
}

}  // namespace

HierarchyPositions hierarchy_positions(const BaseMesh& base, std::span<const SurfacePoint> points, const AddressIndex& index,
                                       std::span<const std::uint8_t> want_limit, std::span<const std::uint8_t> levels) {
    Evaluation<1> evaluation({&base}, points, index);
    const std::vector<std::uint32_t> order = evaluation.insert_all();
    return positions(evaluation, order, want_limit, levels);
}

std::vector<glm::dvec3> hierarchy_values(const BaseMesh& base, std::span<const SurfacePoint> points, const AddressIndex& index,
                                         std::span<const std::uint8_t> levels) {
    Evaluation<1> evaluation({&base}, points, index);
    const std::vector<std::uint32_t> order = evaluation.insert_all();
    return values_at(evaluation, order, levels, 0);
}

HierarchyPositions hierarchy_positions(const BaseMesh& base, std::span<const SurfacePoint> points, const AddressIndex& index,
                                       std::span<const std::uint8_t> want_limit, std::span<const std::uint8_t> levels,
                                       const BaseMesh& channel, std::span<const std::uint8_t> channel_levels,
                                       std::vector<glm::dvec3>& channel_values) {
    Evaluation<2> evaluation({&base, &channel}, points, index);
    const std::vector<std::uint32_t> order = evaluation.insert_all();
    channel_values = values_at(evaluation, order, channel_levels, 1);
    return positions(evaluation, order, want_limit, levels);
}

}  // namespace rgb
