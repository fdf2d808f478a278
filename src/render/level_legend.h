#pragma once
// The legends of the heat maps as screen-space triangles (GL-free), stacked in the bottom-left corner:
// the level heat map's one swatch per level with its number, finest level on top; the distance heat
// map's one swatch per band (colour_map.h) with its range as % of the size and in the mesh's units,
// farthest on top, under a title that gives the size.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace render {

struct OverlayVertex {
    glm::vec2 pixel{0.0f};  // origin at the top left, y down
    glm::vec3 colour{0.0f};
};

std::vector<OverlayVertex> level_legend(int max_level, glm::ivec2 viewport, glm::vec3 text_colour);
// `diagonal`: the length the bands are shares of (SurfaceGeometry::distance_scale).
std::vector<OverlayVertex> distance_legend(double diagonal, glm::ivec2 viewport, glm::vec3 text_colour);

}  // namespace render
