#pragma once
// Helpers for the headless (OSMesa) screenshot tests.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "render/image.h"

namespace render_test {

enum class PixelClass { Background, Neutral, Green, Red, Blue };

// Which RGB-type colour a pixel shows: its dominant channel when it beats the others clearly (shaded
// colours of colour_map.cpp stay well apart); white background; anything else (wire, grey) neutral.
PixelClass classify(glm::u8vec4 pixel);
PixelClass classify(const render::Image& image, int x, int y);

struct PixelCounts {
    std::size_t background = 0, neutral = 0, green = 0, red = 0, blue = 0;
};
PixelCounts count_pixels(const render::Image& image);

// One swatch of the level legend: its colour class and the colour at its middle.
struct Swatch {
    PixelClass kind = PixelClass::Background;
    glm::u8vec4 colour{0};
};
// The level legend's swatches as seen down pixel column `x`: each run of drawn pixels, top to
// bottom, counting from the bottom edge up to the first gap wider than the legend's row spacing (so
// a mesh further up is left out). Runs shorter than `min_run` pixels (text, rim pixels) are skipped.
std::vector<Swatch> legend_column(const render::Image& image, int x, int min_run);
// The classes of those swatches, top to bottom.
std::vector<PixelClass> legend_classes(const std::vector<Swatch>& swatches);

}  // namespace render_test
