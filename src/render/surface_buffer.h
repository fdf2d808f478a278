#pragma once
// The GPU copy of SurfaceGeometry: one vertex buffer, and a second one for the appearance when the
// geometry has one, updated range by range. Counts the bytes it uploads, so benchmarks and tests can
// check that an edit costs what it changed, not the mesh.
#include <cstdint>
#include <span>

#include "render/gl_objects.h"
#include "render/surface_geometry.h"

namespace render {

class SurfaceBuffer {
public:
    SurfaceBuffer();

    // Replaces the whole buffer. `appearance`: empty, or one per vertex.
    void upload_all(std::span<const SurfaceVertex> vertices, std::span<const AppearanceVertex> appearance = {});
    // Uploads only the given face-slot ranges of `vertices` and `appearance` (growing the buffers,
    // with a full upload, when the mesh outgrew them or the appearance came or went).
    void upload(std::span<const SurfaceVertex> vertices, std::span<const AppearanceVertex> appearance,
                std::span<const SlotRange> ranges);
    // Draws every slot; dead slots are degenerate.
    void draw() const;

    std::uint64_t bytes_uploaded() const { return bytes_uploaded_; }
    std::uint64_t upload_calls() const { return upload_calls_; }

private:
    void use_appearance(bool on);

    GlVertexArray vertex_array_;
    GlBuffer buffer_;
    GlBuffer appearance_buffer_;
    std::size_t capacity_ = 0;  // vertices allocated on the GPU
    std::size_t count_ = 0;     // vertices drawn
    bool with_appearance_ = false;
    std::uint64_t bytes_uploaded_ = 0;
    std::uint64_t upload_calls_ = 0;
};

}  // namespace render
