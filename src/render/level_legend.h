#pragma once
// The legend of the level heat map as screen-space triangles (GL-free): one swatch per level with
// its number, stacked in the bottom-left corner, finest level on top.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace render {

struct OverlayVertex {
    glm::vec2 pixel{0.0f};  // origin at the top left, y down
    glm::vec3 colour{0.0f};
};

std::vector<OverlayVertex> level_legend(int max_level, glm::ivec2 viewport, glm::vec3 text_colour);

}  // namespace render
