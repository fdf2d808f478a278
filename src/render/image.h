#pragma once
// An RGBA8 image, rows top to bottom, and its PNG file form.
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec4.hpp>

namespace render {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, first row at the top

    glm::u8vec4 pixel(int x, int y) const {
        const std::size_t i = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
};

// Writes through a temporary file and a rename, so a failure never leaves a half-written PNG.
// Throws std::runtime_error naming the path.
void write_png(const Image& image, const std::filesystem::path& path);
// Throws std::runtime_error naming the path and stb's reason.
Image read_png(const std::filesystem::path& path);

}  // namespace render
