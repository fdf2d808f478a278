#pragma once
// Face-varying texture coordinates of a base mesh (docs/loop-face-varying.md): each triangle corner
// names a UV value; corners of a vertex that share a value and are consecutive around it form a
// span, which is one UV of that vertex. UvLayout classifies every span once, by OpenSubdiv's
// FVAR_LINEAR_* option (§2 of the note), and knows which base edges are UV seams. Everything the
// hierarchy's UVs need beyond the base mesh (uv_evaluator.h) is here; it never changes once built.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "rgb/mesh/vertex_rules.h"
#include "rgb/support/inline_vector.h"

namespace rgb {

class BaseMesh;

// OpenSubdiv's Sdc::Options::FVAR_LINEAR_NONE, _CORNERS_ONLY, _BOUNDARIES, _ALL.
enum class UvInterpolation : std::uint8_t { None, Corners, Boundaries, All };

const char* uv_interpolation_name(UvInterpolation option);  // "none", "corners", "boundaries", "all"
std::optional<UvInterpolation> parse_uv_interpolation(std::string_view name);

struct UvChannel {
    std::vector<glm::dvec2> values;
    std::vector<std::array<std::uint32_t, 3>> corners;  // per base face, its corners' value indices
    UvInterpolation interpolation = UvInterpolation::Corners;
    // Base faces the input gave no texture coordinates (sorted): their corners name placeholder
    // values, which seams keep apart from the others' UVs; savers write these faces without UVs.
    std::vector<std::uint32_t> faces_without_uvs;

    friend bool operator==(const UvChannel&, const UvChannel&) = default;
};

// How a UV value moves from level to level, from the level where a regime starts (as Regime in
// vertex_rules.h): a corner keeps its UV; a crease moves along the two edges bounding its span
// (ring entries `sharp`, read in base faces `end_face`, or in any face joining them to the vertex
// where end_face is kNone); smooth and dart values follow the vertex's own rule on their ring's UVs.
struct UvRegime {
    int start = 0;
    VertexRule rule = VertexRule::Corner;
    std::uint32_t sharp[2] = {0, 0};
    std::uint32_t end_face[2] = {0xffffffffu, 0xffffffffu};
};
using UvRegimes = InlineVector<UvRegime, 11>;

class UvLayout {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    // Throws std::invalid_argument when the channel does not fit the base mesh (a corner count or a
    // value index out of range).
    UvLayout(const BaseMesh& base, UvChannel channel);

    const UvChannel& channel() const { return channel_; }
    UvInterpolation interpolation() const { return channel_.interpolation; }
    const glm::dvec2& corner_uv(std::uint32_t face, int corner) const {
        return channel_.values[channel_.corners[face][static_cast<std::size_t>(corner)]];
    }
    // Whether base halfedge h (3f+i) lies on a UV seam: its two faces disagree on the value at an end.
    bool is_seam(std::uint32_t h) const { return seam_[h] != 0; }
    // The span (one UV of the base vertex) that corner `corner` of base face `face` belongs to.
    std::uint32_t span_of(std::uint32_t face, int corner) const { return span_of_corner_[3 * face + static_cast<std::uint32_t>(corner)]; }
    // A face of the span, the same for all of its corners.
    std::uint32_t span_face(std::uint32_t span) const { return spans_[span].face; }
    // The rules of a span from level 0 on; empty where the span follows its vertex's own rules.
    const UvRegimes& span_regimes(std::uint32_t span) const { return spans_[span].regimes; }

private:
    struct Span {
        std::uint32_t face = 0;
        UvRegimes regimes;
    };
    void classify_vertex(const BaseMesh& base, std::uint32_t v);

    UvChannel channel_;
    std::vector<std::uint8_t> seam_;
    std::vector<std::uint32_t> span_of_corner_;
    std::vector<Span> spans_;
};

}  // namespace rgb
