#include "render/image.h"

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <system_error>

#include <stb_image.h>
#include <stb_image_write.h>

namespace render {

void write_png(const Image& image, const std::filesystem::path& path) {
    std::filesystem::path partial = path;
    partial += ".partial";
    const int ok = stbi_write_png(partial.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4);
    if (ok == 0) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        throw std::runtime_error(path.string() + ": cannot write PNG (is the directory writable?)");
    }
    std::error_code error;
    std::filesystem::rename(partial, path, error);
    if (error) {
        std::filesystem::remove(partial, error);
        throw std::runtime_error(path.string() + ": cannot write PNG: " + error.message());
    }
}

Image read_png(const std::filesystem::path& path) {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(stbi_load(path.c_str(), &width, &height, &channels, 4),
                                                                &stbi_image_free);
    if (!pixels) throw std::runtime_error(path.string() + ": cannot read PNG: " + stbi_failure_reason());
    Image image{width, height, {}};
    image.rgba.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    return image;
}

}  // namespace render
