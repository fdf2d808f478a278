#pragma once
// A 4 x 3 grid with bumps (z = x y mod 3) cut by a UV seam along x = 2, with UVs that need 17 digits;
// optionally with vertex colours (17 digits too) and a one-triangle UV island at (1,1) (2,1) (2,2).
#include <cmath>
#include <string>

#include "io/obj/number_format.h"

namespace rgbio::test {

inline std::string textured_grid(bool colours = false, bool island = false) {
    std::string text;
    for (int y = 0; y <= 3; ++y)
        for (int x = 0; x <= 4; ++x) {
            text += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string((x * y) % 3);
            if (colours) {
                const int i = y * 5 + x;
                append_double(text, std::sqrt(2.0 + i) / 7.0);
                append_double(text, std::log(3.0 + i) / 5.0);
                append_double(text, 1.0 / (3.0 + i));
            }
            text += "\n";
        }
    auto vt = [&](int x, int y, int island) {
        text += "vt";
        append_double(text, std::sqrt(2.0) * x / 7.0 + 0.5 * island);
        append_double(text, std::log(3.0 + y) / 5.0);
        text += '\n';
    };
    // Islands 0 and 1 left and right of the seam, island 2 the one triangle: 20 vt each.
    for (int i = 0; i < (island ? 3 : 2); ++i)
        for (int y = 0; y <= 3; ++y)
            for (int x = 0; x <= 4; ++x) vt(x, y, i);
    auto corner = [](int x, int y, int island) {
        const int v = y * 5 + x + 1;
        return std::to_string(v) + "/" + std::to_string(island * 20 + v);
    };
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            const int i = x < 2 ? 0 : 1, upper = island && x == 1 && y == 1 ? 2 : i;
            text += "f " + corner(x, y, i) + " " + corner(x + 1, y, i) + " " + corner(x + 1, y + 1, i) + "\n";
            text += "f " + corner(x, y, upper) + " " + corner(x + 1, y + 1, upper) + " " + corner(x, y + 1, upper) + "\n";
        }
    return text;
}

}  // namespace rgbio::test
