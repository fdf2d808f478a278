#pragma once
// Exact Loop values of any vertex of the uniform hierarchy Σk, computed from the base mesh alone by
// walking the hierarchy's addresses (surface_point.h), whether or not the adaptive mesh holds the
// vertex or its neighbours. The adaptive mesh uses it where its own neighbourhood lacks what a
// formula needs (a coarser vertex's ring at its own level, spec §4.4); so no extra refinement is
// ever needed for geometry, and every vertex set has its Loop positions.
//
// Every value is computed with the formulas of loop_rules.h from values computed the same way, so it
// equals, bit for bit, what the mesh computes from its own vertices.
//
// Vertices whose rules the base mesh's crease and corner tags change (vertex_rules.h) get all their
// values here, from the closed form of each rule regime (docs/loop-creases.md §4-§5): the mesh asks
// this evaluator for them rather than computing them from its own neighbourhood.
#include <cstdint>

#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/support/key_table.h"

namespace rgb {

class BaseMesh;

class HierarchyEvaluator {
public:
    explicit HierarchyEvaluator(const BaseMesh& base) : base_(base) {}

    // p^l(p) for l = p.level: the position the vertex gets when it is inserted.
    glm::dvec3 insertion_position(const SurfacePoint& p);
    // p^inf(p).
    glm::dvec3 limit_position(const SurfacePoint& p);
    // p^k(p) for k >= p.level.
    glm::dvec3 control_point(const SurfacePoint& p, int k);
    // Values kept from earlier calls.
    std::size_t cached_values() const { return insertion_.size() + limit_.size(); }
    // Forgets every value, keeping the caches' memory: a caller that moves on to another part of the
    // mesh, whose values would no longer be looked up, keeps the caches small and in the processor's.
    void clear() {
        insertion_.clear();
        limit_.clear();
        regime_start_.clear();
        regime_limit_.clear();
    }

private:
    struct Key {
        std::uint32_t face, a0, a1;
        int level;
        // For the regime caches, the start level of the regime (-1 elsewhere): with the point's own key
        // it tells regimes apart, without meeting another point's key.
        int regime = -1;
        friend bool operator==(const Key&, const Key&) = default;
    };
    struct KeyHash {
        // Every field reaches the low bits, which pick the slot (key_table.h): a splitmix64 finish.
        std::size_t operator()(const Key& k) const noexcept {
            std::uint64_t h = (std::uint64_t(k.face) << 32 | k.a0) * 0x9e3779b97f4a7c15ull ^
                              (std::uint64_t(k.a1) << 16 | std::uint64_t(k.level & 0xff) << 8 | (std::uint64_t(k.regime + 1) & 0xff));
            h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
            h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
            return static_cast<std::size_t>(h ^ (h >> 31));
        }
    };
    Key key(const SurfacePoint& p) const;
    double gamma(const SurfacePoint& p) const;

    // Tagged vertices: p^k from the regime containing k, the value a regime starts from, and the
    // limit of a regime's rule from its start level's data.
    glm::dvec3 tagged_control_point(const SurfacePoint& p, int k);
    glm::dvec3 regime_start_value(const SurfacePoint& p, const Regimes& regimes, std::size_t i);
    glm::dvec3 regime_value(const SurfacePoint& p, const Regime& r, const glm::dvec3& start, int k);
    glm::dvec3 regime_limit(const SurfacePoint& p, const Regime& r, const glm::dvec3& start);
    // p^t of p's neighbours in Σt, in vertex_rules' ring order.
    std::vector<glm::dvec3> ring_values(const SurfacePoint& p, int t);
    // The second eigenvalue of a rule that has one (smooth, crease, corner).
    double regime_gamma(const SurfacePoint& p, VertexRule rule) const;

    const BaseMesh& base_;
    KeyTable<Key, KeyHash, glm::dvec3> insertion_, limit_;
    // Per regime of a tagged vertex (Key.regime holds the regime's start level): its start value and
    // its limit.
    KeyTable<Key, KeyHash, glm::dvec3> regime_start_, regime_limit_;
};

}  // namespace rgb
