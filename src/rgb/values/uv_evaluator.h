#pragma once
// Exact face-varying UVs of any vertex of the uniform hierarchy Σk (docs/loop-face-varying.md),
// computed from the base mesh's UV layout alone by the vertex's address, as hierarchy_evaluator.h
// does for positions: a UV is a pure function of (address, UV value, level), never of the operators
// that built an adaptive mesh, so adaptive meshes agree with uniform ones and with OpenSubdiv's Far.
//
// A point has one UV value, except on a UV seam, where each side has its own: the value is named
// by the base face the point is given in (a corner of the adaptive mesh asks in the base face its
// triangle lies in). Each value follows its regimes (uv_layout.h) by the closed forms of §4 of the
// note: smooth and dart values the vertex's own Loop rules on their ring's UVs, creases the boundary
// rule along their span's bounding edges, corners stay put.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"
#include "rgb/values/uv_layout.h"

namespace rgb {

class BaseMesh;

class UvEvaluator {
public:
    // Both must outlive the evaluator; `layout` must have been built for `base`.
    UvEvaluator(const BaseMesh& base, const UvLayout& layout) : base_(base), layout_(layout) {}

    // uv^k of p's value on the side of base face p.face, for k >= p.level: the UV that the corners
    // of p in that face carry in Σk.
    glm::dvec2 control_uv(const SurfacePoint& p, int k);
    // uv^inf: the limit of the value's last regime, with exact weights (Far's LimitFaceVarying uses
    // float weights at UV creases, docs/loop-face-varying.md §5).
    glm::dvec2 limit_uv(const SurfacePoint& p);
    // Room for about this many values, so that evaluating a whole mesh does not rehash as it goes.
    void reserve(std::size_t values) { values_.reserve(values); }
    const UvLayout& layout() const { return layout_; }
    std::size_t cached_values() const { return values_.size() + regime_start_.size() + regime_limit_.size(); }

private:
    struct Key {
        std::uint32_t face, a0, a1;
        int level;
        std::uint32_t value;  // the span of a base vertex, the face of a seam's side, else kNone
        int regime = -1;      // for the regime caches: the regime's start level
        friend bool operator==(const Key&, const Key&) = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const noexcept {
            // Every field multiplied by its own odd constant, then a 64-bit finaliser: the addresses of
            // one level differ in few low bits, which a plain shift-and-xor leaves clustered.
            std::uint64_t h = k.face * 0x9e3779b97f4a7c15ull ^ k.a0 * 0xc2b2ae3d27d4eb4full ^ k.a1 * 0x165667b19e3779f9ull ^
                              static_cast<std::uint64_t>(k.level * 64 + k.regime + 1) * 0x27d4eb2f165667c5ull ^
                              k.value * 0xff51afd7ed558ccdull;
            h ^= h >> 31;
            h *= 0x94d049bb133111ebull;
            return static_cast<std::size_t>(h ^ (h >> 29));
        }
    };
    // The address of p's value that every computation starts from (p given on the value's side), so
    // that its bits never depend on which address a caller had.
    SurfacePoint representative(const SurfacePoint& p) const;
    // Names p's value: the same key for every address of a point on the same side.
    Key key(const SurfacePoint& p) const;
    UvRegimes regimes(const SurfacePoint& p) const;

    // A value's UV at its own level and, once needed, the limit of its first regime: kept together so
    // that a neighbour's UV at any level of that regime costs one lookup.
    struct Values {
        glm::dvec3 insertion{0.0}, first_limit{0.0};
        bool first_limit_known = false;
    };
    // The entry of p's value, its insertion UV computed if new. References stay valid (node map).
    Values& values(const SurfacePoint& p);

    // UVs are carried as (u, v, 0) so that loop_rules.h's formulas apply unchanged; p is a representative.
    glm::dvec3 insertion(const SurfacePoint& p);
    glm::dvec3 control(const SurfacePoint& p, int k);
    glm::dvec3 regime_start_value(const SurfacePoint& p, const UvRegimes& regimes, std::size_t i);
    // `first`: p's entry when r is p's first regime (its limit is kept there), else nullptr.
    glm::dvec3 regime_value(const SurfacePoint& p, const UvRegime& r, const glm::dvec3& start, int k, Values* first);
    glm::dvec3 regime_limit(const SurfacePoint& p, const UvRegime& r, const glm::dvec3& start, Values* first);
    // uv^t of p's neighbours in Σt, in ring_at's order, each on p's side.
    std::vector<glm::dvec3> ring_values(const SurfacePoint& p, int t);
    // uv^t of ring entry q of p, read in base face `face` (kNone: the face q is given in, which joins
    // it to p).
    glm::dvec3 neighbour_value(const SurfacePoint& q, std::uint32_t face, int t);
    double regime_gamma(const SurfacePoint& p, VertexRule rule) const;

    const BaseMesh& base_;
    const UvLayout& layout_;
    std::unordered_map<Key, Values, KeyHash> values_;
    // Later regimes of values with several (semi-sharp and tagged vertices): their start and limit.
    std::unordered_map<Key, glm::dvec3, KeyHash> regime_start_, regime_limit_;
};

}  // namespace rgb
