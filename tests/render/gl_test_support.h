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
PixelClass classify(const render::Image& image, int x, int y);

struct PixelCounts {
    std::size_t background = 0, neutral = 0, green = 0, red = 0, blue = 0;
};
PixelCounts count_pixels(const render::Image& image);

// The level legend's swatches as seen down pixel column `x`: the colour class of each run of drawn
// pixels, top to bottom, counting from the bottom edge up to the first gap wider than the legend's
// row spacing (so a mesh further up is left out). Runs shorter than `min_run` pixels (text, rim
// pixels) are skipped.
std::vector<PixelClass> legend_column(const render::Image& image, int x, int min_run);

}  // namespace render_test
