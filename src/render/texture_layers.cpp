#include "render/texture_layers.h"

#include <algorithm>
#include <stdexcept>

#include <stb_image_resize.h>

namespace render {
namespace {

// `image` as `width` x `height` pixels, rows bottom-up, appended to `out`.
void append_layer(const Image& image, int width, int height, std::vector<std::uint8_t>& out) {
    const std::size_t row = 4 * std::size_t(width);
    std::vector<std::uint8_t> scaled;
    const std::vector<std::uint8_t>* pixels = &image.rgba;
    if (image.width != width || image.height != height) {
        scaled.resize(row * std::size_t(height));
        if (stbir_resize_uint8(image.rgba.data(), image.width, image.height, 0, scaled.data(), width, height, 0, 4) == 0)
            throw std::runtime_error("cannot scale a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " texture");
        pixels = &scaled;
    }
    for (int y = height - 1; y >= 0; --y) {
        const auto first = pixels->begin() + static_cast<std::ptrdiff_t>(row * std::size_t(y));
        out.insert(out.end(), first, first + static_cast<std::ptrdiff_t>(row));
    }
}

}  // namespace

TextureLayers texture_layers(const std::vector<Image>& images, std::size_t max_bytes) {
    TextureLayers layers;
    for (const Image& image : images) {
        layers.width = std::max(layers.width, std::min(image.width, kMaxTextureSide));
        layers.height = std::max(layers.height, std::min(image.height, kMaxTextureSide));
    }
    while (layers.width > 1 && layers.height > 1 &&
           4 * std::size_t(layers.width) * std::size_t(layers.height) * images.size() > max_bytes) {
        layers.width /= 2;
        layers.height /= 2;
    }
    layers.rgba.reserve(4 * std::size_t(layers.width) * std::size_t(layers.height) * images.size());
    for (const Image& image : images) append_layer(image, layers.width, layers.height, layers.rgba);
    return layers;
}

}  // namespace render
