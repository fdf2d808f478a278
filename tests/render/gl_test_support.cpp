#include "gl_test_support.h"

#include <algorithm>

namespace render_test {

PixelClass classify(const render::Image& image, int x, int y) { return classify(image.pixel(x, y)); }

PixelClass classify(glm::u8vec4 p) {
    if (p.r == 255 && p.g == 255 && p.b == 255) return PixelClass::Background;
    constexpr int kMargin = 40;  // out of 255
    const int r = p.r, g = p.g, b = p.b;
    if (g > std::max(r, b) + kMargin) return PixelClass::Green;
    if (r > std::max(g, b) + kMargin) return PixelClass::Red;
    if (b > std::max(r, g) + kMargin) return PixelClass::Blue;
    return PixelClass::Neutral;
}

PixelCounts count_pixels(const render::Image& image) {
    PixelCounts counts;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) switch (classify(image, x, y)) {
                case PixelClass::Background: ++counts.background; break;
                case PixelClass::Neutral: ++counts.neutral; break;
                case PixelClass::Green: ++counts.green; break;
                case PixelClass::Red: ++counts.red; break;
                case PixelClass::Blue: ++counts.blue; break;
            }
    return counts;
}

std::vector<Swatch> legend_column(const render::Image& image, int x, int min_run) {
    constexpr int kMaxGap = 8;  // rows of the legend are 4 pixels apart
    std::vector<Swatch> runs;   // bottom to top
    int run = 0, gap = 0;
    for (int y = image.height - 1; y >= 0; --y) {
        if (classify(image, x, y) == PixelClass::Background) {
            if (run >= min_run) runs.push_back({classify(image, x, y + 1 + run / 2), image.pixel(x, y + 1 + run / 2)});
            run = 0;
            if (!runs.empty() && ++gap > kMaxGap) break;
            continue;
        }
        gap = 0;
        ++run;
    }
    return {runs.rbegin(), runs.rend()};
}

std::vector<PixelClass> legend_classes(const std::vector<Swatch>& swatches) {
    std::vector<PixelClass> classes;
    for (const Swatch& s : swatches) classes.push_back(s.kind);
    return classes;
}

}  // namespace render_test
