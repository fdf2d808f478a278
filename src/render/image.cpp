#include "render/image.h"

#include <cstdlib>
#include <memory>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

namespace render {

namespace {

extern "C" void append_to_string(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

Image to_image(stbi_uc* decoded, int width, int height, const std::string& source) {
    const std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(decoded, &stbi_image_free);
    if (!pixels) throw std::runtime_error(source + ": cannot read the image: " + stbi_failure_reason());
    Image image{width, height, {}};
    image.rgba.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    return image;
}

}  // namespace

std::string encode_png(const Image& image) {
    std::string png;
    if (stbi_write_png_to_func(append_to_string, &png, image.width, image.height, 4, image.rgba.data(), image.width * 4) == 0)
        throw std::runtime_error("cannot encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " PNG");
    return png;
}

Image decode_png(const std::string& png) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* decoded = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), static_cast<int>(png.size()), &width,
                                             &height, &channels, 4);
    return to_image(decoded, width, height, "PNG data");
}

Image read_image(const std::filesystem::path& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* decoded = stbi_load(path.c_str(), &width, &height, &channels, 4);
    return to_image(decoded, width, height, path.string());
}

Image BoundedImageReader::read(const std::filesystem::path& path) {
    int width = 0, height = 0, channels = 0;
    if (stbi_info(path.c_str(), &width, &height, &channels) == 0)
        throw std::runtime_error(path.string() + ": cannot read the image: " + stbi_failure_reason());
    const std::string size = std::to_string(width) + "x" + std::to_string(height) + " pixels";
    if (width > kMaxImageSide || height > kMaxImageSide)
        throw std::runtime_error(size + ", more than " + std::to_string(kMaxImageSide) + " on a side");
    const std::size_t bytes = 4 * std::size_t(width) * std::size_t(height);
    if (decoded_bytes_ + bytes > kMaxDecodedBytes)
        throw std::runtime_error(size + ": with the textures before it, more than " + std::to_string(kMaxDecodedBytes >> 20) + " MB decoded");
    Image image = read_image(path);
    decoded_bytes_ += image.rgba.size();
    return image;
}

}  // namespace render
