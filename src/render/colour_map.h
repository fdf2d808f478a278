#pragma once
// Display colours, GL-free so the editor's legend and the shaders agree (the renderer uploads these).
#include <glm/vec3.hpp>

#include "rgb/face_type.h"

namespace render {

// The paper's picture: green, red and blue triangles.
glm::vec3 rgb_type_colour(rgb::Colour colour);

// Heat map over the levels present: level 0 is blue, `max_level` is red.
glm::vec3 level_colour(int level, int max_level);

// Levels beyond this share the last colour (the shader's palette size).
inline constexpr int kMaxLevelColours = 32;

}  // namespace render
