#pragma once
// A headless OpenGL 3.3 core context rendering into memory through OSMesa (llvmpipe): no display
// needed, and the output is byte-for-byte deterministic. Construction makes it current and loads
// the GL entry points, after which Renderer works exactly as in a window.
#include <cstdint>
#include <vector>

#include "render/image.h"

namespace render {

class OffscreenContext {
public:
    // Throws std::runtime_error if OSMesa cannot create a 3.3 core context.
    OffscreenContext(int width, int height);
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    void make_current();
    // Waits for rendering to finish and returns the default framebuffer, top row first.
    Image read_pixels() const;

private:
    int width_;
    int height_;
    std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer, bottom row first
    void* context_ = nullptr;           // OSMesaContext, kept opaque to keep GL/osmesa.h out of headers
};

}  // namespace render
