#include "render/level_legend.h"

#include <array>
#include <string>

#include <stb_easy_font.h>

#include "render/colour_map.h"

namespace render {
namespace {

constexpr float kMargin = 12.0f;
constexpr float kSwatch = 16.0f;
constexpr float kRowGap = 4.0f;
constexpr float kTextScale = 2.0f;  // stb_easy_font glyphs are about 7 pixels tall

void add_quad(std::vector<OverlayVertex>& out, glm::vec2 a, glm::vec2 b, glm::vec3 colour) {
    const std::array<glm::vec2, 6> corners{a, {b.x, a.y}, b, a, b, {a.x, b.y}};
    for (const glm::vec2& p : corners) out.push_back({p, colour});
}

void add_text(std::vector<OverlayVertex>& out, std::string text, glm::vec2 origin, glm::vec3 colour) {
    // stb_easy_font writes quads of 16-byte vertices (x, y, z, rgba8).
    struct FontVertex {
        float x, y, z;
        unsigned char rgba[4];
    };
    std::array<FontVertex, 1024> buffer{};
    const int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, buffer.data(), sizeof(buffer));
    for (int q = 0; q < quads; ++q) {
        const FontVertex& lo = buffer[static_cast<std::size_t>(4 * q)];
        const FontVertex& hi = buffer[static_cast<std::size_t>(4 * q + 2)];
        add_quad(out, origin + kTextScale * glm::vec2(lo.x, lo.y), origin + kTextScale * glm::vec2(hi.x, hi.y), colour);
    }
}

}  // namespace

std::vector<OverlayVertex> level_legend(int max_level, glm::ivec2 viewport, glm::vec3 text_colour) {
    std::vector<OverlayVertex> out;
    const float row = kSwatch + kRowGap;
    for (int level = 0; level <= max_level; ++level) {
        const float top = static_cast<float>(viewport.y) - kMargin - static_cast<float>(level + 1) * row + kRowGap;
        add_quad(out, {kMargin, top}, {kMargin + kSwatch, top + kSwatch}, level_colour(level));
        add_text(out, "level " + std::to_string(level), {kMargin + kSwatch + 6.0f, top + 1.0f}, text_colour);
    }
    return out;
}

}  // namespace render
