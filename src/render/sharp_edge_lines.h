#pragma once
// The mesh's edges along tagged base edges (as rgb/mesh/sharp_edges.h finds them) as line segments at
// the corners the surface shows (GL-free), so that creases are drawn as coloured lines over the
// surface. Followed slot by slot: after a change only the face slots it rewrote are looked at again,
// so that the editor draws them every frame at millions of triangles (a look at every slot takes a
// tenth of a second there).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"

namespace rgb {
class Mesh;
}

namespace render {

class SurfaceGeometry;
struct SlotRange;

class SharpEdgeLines {
public:
    // Looks at every face slot of `mesh`.
    void rebuild(const rgb::Mesh& mesh);
    // Looks again at the face slots in `changed` (those the surface's geometry rewrote).
    void update(const rgb::Mesh& mesh, std::span<const SlotRange> changed);
    // Endpoint pairs, one pair per sharp edge, at the corners `geometry` shows for its face slot;
    // empty for a base mesh without tagged edges.
    std::vector<glm::vec3> lines(const SurfaceGeometry& geometry) const;

private:
    void look_at(const rgb::Mesh& mesh, rgb::FaceId f);

    // By face slot: bit i set when the face's side from corner i to corner i + 1 is drawn (each
    // sharp edge by the side that runs from its lower vertex id, which stays the same while the
    // faces beside it change).
    std::vector<std::uint8_t> sides_;
    std::size_t slots_with_sides_ = 0;
};

}  // namespace render
