#pragma once
// Helpers for the headless (OSMesa) screenshot tests.
#include <cstddef>

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

}  // namespace render_test
