#pragma once
// An RGBA8 image, rows top to bottom, its PNG form, and image files read with stb_image.
#include <cstddef>
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

// Images read for a preview are refused above this many pixels on a side (a 389 KB PNG can say
// 20000x20000, 1.6 GB decoded), and, read one after another, above kMaxDecodedBytes in all.
inline constexpr int kMaxImageSide = 8192;
inline constexpr std::size_t kMaxDecodedBytes = std::size_t(1) << 30;
// Reads images for a preview: the header first, and refuses (std::runtime_error, saying why) an
// image over kMaxImageSide on a side or one that would take the images read so far past
// kMaxDecodedBytes, before decoding it.
class BoundedImageReader {
public:
    Image read(const std::filesystem::path& path);

private:
    std::size_t decoded_bytes_ = 0;
};

}  // namespace render
