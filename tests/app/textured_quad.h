#pragma once
// A textured file for the display's texture tests: the unit square [0, 1]^2 in the plane z = 0,
// facing +z, as two triangles whose texture coordinates are (x, y), with material "skin" (Kd green)
// whose map_Kd is `texture`. halves.png, the texture the square is meant to have, is 64 x 64 texels
// (large enough that filtering blends little): red where u < 0.5, blue where u > 0.5.
#include <filesystem>
#include <string>

namespace app::test {

inline constexpr int kHalvesSide = 64;

// Writes quad.obj, quad.mtl and halves.png into `folder` (emptied first); returns quad.obj's path.
std::filesystem::path write_textured_quad(const std::filesystem::path& folder, const std::string& texture = "halves.png");

}  // namespace app::test
