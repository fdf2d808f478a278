#include "render/colour_map.h"

#include <algorithm>
#include <array>

namespace render {

glm::vec3 rgb_type_colour(rgb::Colour colour) {
    switch (colour) {
        case rgb::Colour::Green: return {0.30f, 0.78f, 0.32f};
        case rgb::Colour::Red: return {0.88f, 0.26f, 0.22f};
        case rgb::Colour::Blue: return {0.26f, 0.42f, 0.92f};
    }
    return {1.0f, 1.0f, 1.0f};
}

glm::vec3 level_colour(int level) {
    // Neighbouring levels differ in hue; the brightest colours sit in the middle, where painting
    // usually happens.
    static constexpr std::array<glm::vec3, 13> table{
        glm::vec3(0.18f, 0.30f, 0.90f), glm::vec3(0.10f, 0.62f, 0.90f), glm::vec3(0.10f, 0.78f, 0.70f),
        glm::vec3(0.30f, 0.80f, 0.25f), glm::vec3(0.70f, 0.86f, 0.15f), glm::vec3(0.98f, 0.82f, 0.15f),
        glm::vec3(0.98f, 0.55f, 0.10f), glm::vec3(0.90f, 0.22f, 0.15f), glm::vec3(0.80f, 0.15f, 0.50f),
        glm::vec3(0.60f, 0.25f, 0.78f), glm::vec3(0.42f, 0.30f, 0.62f), glm::vec3(0.55f, 0.55f, 0.55f),
        glm::vec3(0.92f, 0.92f, 0.92f)};
    return table[static_cast<std::size_t>(std::clamp(level, 0, static_cast<int>(table.size()) - 1))];
}

int distance_band(double fraction) {
    return static_cast<int>(std::ranges::upper_bound(kDistanceBandEdges, fraction) - kDistanceBandEdges.begin());
}

glm::vec3 distance_colour(int band) {
    // Dark blue to cyan, green, yellow, orange and red: neighbouring bands differ in hue, and far reads as hot.
    static constexpr std::array<glm::vec3, kDistanceBands> table{
        glm::vec3(0.16f, 0.20f, 0.55f), glm::vec3(0.15f, 0.38f, 0.85f), glm::vec3(0.10f, 0.60f, 0.92f),
        glm::vec3(0.10f, 0.76f, 0.72f), glm::vec3(0.28f, 0.80f, 0.35f), glm::vec3(0.65f, 0.86f, 0.18f),
        glm::vec3(0.98f, 0.84f, 0.15f), glm::vec3(0.98f, 0.58f, 0.10f), glm::vec3(0.92f, 0.33f, 0.12f),
        glm::vec3(0.78f, 0.12f, 0.14f), glm::vec3(0.50f, 0.04f, 0.30f)};
    return table[static_cast<std::size_t>(std::clamp(band, 0, kDistanceBands - 1))];
}

glm::vec3 checker_colour(int parity) { return parity % 2 == 0 ? glm::vec3(0.93f, 0.93f, 0.9f) : glm::vec3(0.2f, 0.3f, 0.55f); }

}  // namespace render
