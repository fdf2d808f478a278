#pragma once
// An RGBA8 image, rows top to bottom, its PNG form, and image files read with stb_image.
#include <cstdint>
#include <filesystem>
#include <string>
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

// The PNG file's bytes, made in memory so that callers save them with rgbio::AtomicFileWriter (the
// render layer does no file writing of its own). Throws std::runtime_error if stb cannot encode.
std::string encode_png(const Image& image);
// Throw std::runtime_error naming the source and stb's reason.
Image decode_png(const std::string& png);
// Any format stb_image reads (PNG, JPEG, TGA, BMP, ...), converted to RGBA8.
Image read_image(const std::filesystem::path& path);

}  // namespace render
