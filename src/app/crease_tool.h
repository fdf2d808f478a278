#pragma once
// The editor's crease tool (issue 13): with it active, a left click or drag tags the base edges it
// passes as infinitely sharp creases, Shift+drag untags them. Tags belong to the base mesh, so a drag
// becomes one undoable edit giving the whole mesh new tags on release (Document::set_sharp_features:
// the vertex set stays, every position follows the new rules). Also: tagging every edge above an
// angle, clearing all tags, and the boundary option. GL-free; the editor feeds it surface hits.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "app/surface_picking.h"
#include "render/surface_geometry.h"
#include "rgb/mesh/mesh.h"
#include "rgb/rules/sharp_features.h"

namespace app {

struct CreaseToolSettings {
    bool active = false;         // the left button tags edges instead of painting levels
    float reach_px = 8.0f;       // how close to an edge the cursor must pass, in screen pixels
    float sharp_angle_deg = 30.0f;  // for "tag edges above the angle"
};

// A base edge, smaller vertex first.
using BaseEdge = std::pair<std::uint32_t, std::uint32_t>;

// The interior base edge nearest to a hit on the displayed surface, if the displayed surface passes
// it within `reach_world`: among the faces within reach of the hit, the mesh edges that lie on base
// edges, measured as drawn.
std::optional<BaseEdge> base_edge_near(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                       const SurfaceHit& hit, double reach_world);

// The mesh's tags with `edges` tagged infinitely sharp (or untagged).
rgb::SharpFeatures with_edges(const rgb::SharpFeatures& features, const std::vector<BaseEdge>& edges, bool untag);
// The mesh's tags plus every interior base edge above the angle.
rgb::SharpFeatures with_edges_above(const rgb::Mesh& mesh, double degrees);

// One drag of the tool: the edges it touched, in the order it touched them.
class CreaseDrag {
public:
    explicit CreaseDrag(bool untag) : untag_(untag) {}
    bool untag() const { return untag_; }
    void touch(const BaseEdge& edge);
    const std::vector<BaseEdge>& edges() const { return edges_; }
    // The tags after the drag, or nothing when it changes none.
    std::optional<rgb::SharpFeatures> result(const rgb::SharpFeatures& before) const;

private:
    bool untag_;
    std::vector<BaseEdge> edges_;
};

}  // namespace app
