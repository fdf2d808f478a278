#pragma once
// The diffuse textures of a mesh's materials as one stack of equally sized layers, ready for an
// OpenGL 2D array texture (the renderer's texture mode picks a layer per face, which separate
// textures cannot do in one draw). GL-free: the editor prepares them while it reads the file.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/image.h"

namespace render {

// Layers larger than this on a side are scaled down (GL 3.3 guarantees 1024; every driver we meet
// has at least 8192): memory for a preview stays bounded.
inline constexpr int kMaxTextureSide = 4096;
// All layers together are scaled down (halving their sides) until they fit this, so that a file
// with many large textures cannot exhaust memory for its preview.
inline constexpr std::size_t kMaxTextureBytes = std::size_t(256) << 20;

struct TextureLayers {
    int width = 0;
    int height = 0;
    // count() layers of width * height RGBA8 pixels, each with its first row at texture coordinate
    // v = 0: the bottom of the image, as OBJ's texture coordinates and OpenGL read it.
    std::vector<std::uint8_t> rgba;

    std::size_t count() const { return width > 0 && height > 0 ? rgba.size() / (4 * std::size_t(width) * std::size_t(height)) : 0; }
};

// The images, in order, each scaled to the largest width and the largest height among them (at most
// kMaxTextureSide, and `max_bytes` in all) and flipped to bottom-up rows.
TextureLayers texture_layers(const std::vector<Image>& images, std::size_t max_bytes = kMaxTextureBytes);

}  // namespace render
