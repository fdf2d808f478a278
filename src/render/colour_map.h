#pragma once
// Display colours, GL-free so the editor's legend and the shaders agree (the renderer uploads these).
#include <glm/vec3.hpp>

#include "rgb/rules/face_type.h"

namespace render {

// The paper's picture: green, red and blue triangles.
glm::vec3 rgb_type_colour(rgb::Colour colour);

// Heat map of face levels: one fixed colour per level (blue at 0 through green and yellow to red,
// then purple), so a level looks the same in every picture whatever else is on screen. Levels past
// the table share its last colour.
glm::vec3 level_colour(int level);

// The texture checker (Colouring::Checker): cells of kCheckerCells per unit of texture coordinate,
// cell (i, j) in checker_colour((i + j) mod 2): 0 light grey, 1 dark blue.
inline constexpr float kCheckerCells = 8.0f;
glm::vec3 checker_colour(int parity);

// Levels beyond this share the last colour (the shader's palette size).
inline constexpr int kMaxLevelColours = 32;

}  // namespace render
