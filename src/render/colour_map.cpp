#include "render/colour_map.h"

#include <algorithm>
#include <array>

#include <glm/common.hpp>

namespace render {

glm::vec3 rgb_type_colour(rgb::Colour colour) {
    switch (colour) {
        case rgb::Colour::Green: return {0.30f, 0.78f, 0.32f};
        case rgb::Colour::Red: return {0.88f, 0.26f, 0.22f};
        case rgb::Colour::Blue: return {0.26f, 0.42f, 0.92f};
    }
    return {1.0f, 1.0f, 1.0f};
}

glm::vec3 level_colour(int level, int max_level) {
    // Blue, cyan, green, yellow, red: distinct hues for neighbouring levels.
    static constexpr std::array<glm::vec3, 5> stops{glm::vec3(0.18f, 0.30f, 0.90f), glm::vec3(0.10f, 0.75f, 0.85f),
                                                   glm::vec3(0.25f, 0.80f, 0.25f), glm::vec3(0.95f, 0.85f, 0.15f),
                                                   glm::vec3(0.90f, 0.20f, 0.15f)};
    const float t = max_level > 0 ? std::clamp(static_cast<float>(level) / static_cast<float>(max_level), 0.0f, 1.0f) : 0.0f;
    const float x = t * static_cast<float>(stops.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), stops.size() - 2);
    return glm::mix(stops[i], stops[i + 1], x - static_cast<float>(i));
}

}  // namespace render
