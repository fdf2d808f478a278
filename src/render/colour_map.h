#pragma once
// Display colours, GL-free so the editor's legend and the shaders agree (the renderer uploads these).
#include <array>

#include <glm/vec3.hpp>

#include "rgb/rules/face_type.h"

namespace render {

// Faces without a colouring of their own (Colouring::Plain, and data the file does not give).
inline constexpr glm::vec3 kPlainColour{0.78f, 0.78f, 0.76f};

// The paper's picture: green, red and blue triangles.
glm::vec3 rgb_type_colour(rgb::Colour colour);

// Heat map of face levels: one fixed colour per level (blue at 0 through green and yellow to red,
// then purple), so a level looks the same in every picture whatever else is on screen. Levels past
// the table share its last colour.
glm::vec3 level_colour(int level);

// Heat map of the distance to the dense mesh of a cage with detail (Colouring::DetailDistance): each
// face's largest departure from it (rgb::face_surface_error) as a share of the mesh's size
// (rgb::bounding_box_diagonal), in fixed bands with 1-2-5 steps from 1e-5 to 1e-2 of the size, one
// colour each from blue (close) to dark red (far); band 0 below 1e-5, the last at 1e-2 and above.
// Logarithmic, as the errors of successive levels differ by factors, not by amounts; fixed, so that
// a colour means the same distance in every picture and through every edit (a face's colour changes
// only when the face does; a scale relative to the largest error would recolour the whole mesh with
// every dab that changes it, and always paint the worst face red, however good). 1% of the size is
// a shape visibly off from any view of the whole mesh; 0.001% is a hundredth of a pixel with the mesh
// 1000 pixels across.
inline constexpr std::array<double, 10> kDistanceBandEdges{1e-5, 2e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2};
inline constexpr int kDistanceBands = static_cast<int>(kDistanceBandEdges.size()) + 1;
// The band of a distance that is `fraction` of the size: how many band edges are at or below it.
int distance_band(double fraction);
glm::vec3 distance_colour(int band);

// The texture checker (Colouring::Checker): cells of kCheckerCells per unit of texture coordinate,
// cell (i, j) in checker_colour((i + j) mod 2): 0 light grey, 1 dark blue.
inline constexpr float kCheckerCells = 8.0f;
glm::vec3 checker_colour(int parity);

// Levels beyond this share the last colour (the shader's palette size).
inline constexpr int kMaxLevelColours = 32;

}  // namespace render
