#include "render/level_legend.h"

#include <array>
#include <cstdio>
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
    // A glyph is at most a dozen or so quads of four vertices.
    std::vector<FontVertex> buffer(64 * (text.size() + 1));
    const int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, buffer.data(), static_cast<int>(buffer.size() * sizeof(FontVertex)));
    for (int q = 0; q < quads; ++q) {
        const FontVertex& lo = buffer[static_cast<std::size_t>(4 * q)];
        const FontVertex& hi = buffer[static_cast<std::size_t>(4 * q + 2)];
        add_quad(out, origin + kTextScale * glm::vec2(lo.x, lo.y), origin + kTextScale * glm::vec2(hi.x, hi.y), colour);
    }
}

// The top of row `row` (0 at the bottom).
float row_top(int row, glm::ivec2 viewport) {
    return static_cast<float>(viewport.y) - kMargin - static_cast<float>(row + 1) * (kSwatch + kRowGap) + kRowGap;
}

void add_row(std::vector<OverlayVertex>& out, int row, glm::ivec2 viewport, glm::vec3 colour, const std::string& text, glm::vec3 text_colour) {
    const float top = row_top(row, viewport);
    add_quad(out, {kMargin, top}, {kMargin + kSwatch, top + kSwatch}, colour);
    add_text(out, text, {kMargin + kSwatch + 6.0f, top + 1.0f}, text_colour);
}

// A number with `digits` significant digits, as printf's %g writes it.
std::string number(double value, int digits) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.*g", digits, value);
    return text.data();
}

}  // namespace

std::vector<OverlayVertex> level_legend(int max_level, glm::ivec2 viewport, glm::vec3 text_colour) {
    std::vector<OverlayVertex> out;
    for (int level = 0; level <= max_level; ++level)
        add_row(out, level, viewport, level_colour(level), "level " + std::to_string(level), text_colour);
    return out;
}

std::vector<OverlayVertex> distance_legend(double diagonal, glm::ivec2 viewport, glm::vec3 text_colour) {
    std::vector<OverlayVertex> out;
    const auto percent = [](double fraction) { return number(100.0 * fraction, 3); };
    const auto units = [&](double fraction) { return number(fraction * diagonal, 2); };
    const std::size_t edges = kDistanceBandEdges.size();
    for (int band = 0; band < kDistanceBands; ++band) {
        const auto b = static_cast<std::size_t>(band);
        std::string range;
        if (b == 0) range = "< " + percent(kDistanceBandEdges[0]) + "%   < " + units(kDistanceBandEdges[0]);
        else if (b == edges) range = "> " + percent(kDistanceBandEdges[b - 1]) + "%   > " + units(kDistanceBandEdges[b - 1]);
        else
            range = percent(kDistanceBandEdges[b - 1]) + "-" + percent(kDistanceBandEdges[b]) + "%   " + units(kDistanceBandEdges[b - 1]) +
                    "-" + units(kDistanceBandEdges[b]);
        add_row(out, band, viewport, distance_colour(band), range, text_colour);
    }
    // The title, without a swatch, above the bands.
    add_text(out, "distance to the dense mesh (% of size " + number(diagonal, 3) + "; units)", {kMargin, row_top(kDistanceBands, viewport) + 1.0f},
             text_colour);
    return out;
}

}  // namespace render
