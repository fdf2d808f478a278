#pragma once
// What the input file says about the surface's look, for the editor's material, vertex colour and
// texture checker modes. Indexed by base face and base vertex (like rgbio::BaseAttributes, which the
// app converts: render does not read files), so refinement never changes it; a face of the adaptive
// mesh takes it from the base face it lies in, with vertex colours and texture coordinates
// interpolated linearly over that base face. This is a preview: saved files keep texture coordinates
// and colours at level 0 only, until the core subdivides them by their own Loop rules.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "rgb/handles.h"

namespace rgb {
class Mesh;
}

namespace render {

struct SurfaceAppearance {
    // Empty, or per base face: its material's diffuse colour (nullopt: no material).
    std::vector<std::optional<glm::vec3>> face_colours;
    std::vector<glm::vec3> vertex_colours;  // empty, or per base vertex
    // Empty, or per base face: its corners' texture coordinates (nullopt: the face has none).
    std::vector<std::optional<std::array<glm::vec2, 3>>> corner_texcoords;

    bool empty() const { return face_colours.empty() && vertex_colours.empty() && corner_texcoords.empty(); }
};

// Per vertex of the surface buffer, beside SurfaceVertex: colours as RGBA8 (alpha 255 where the
// file gives one, 0 where not) and the texture coordinate (0, 0 where the file gives none).
struct AppearanceVertex {
    std::uint32_t material_rgba = 0;
    std::uint32_t vertex_rgba = 0;
    glm::vec2 texcoord{0.0f};

    friend bool operator==(const AppearanceVertex&, const AppearanceVertex&) = default;
};
static_assert(sizeof(AppearanceVertex) == 16, "the vertex layout in surface_buffer.cpp assumes packed fields");

// A colour in [0, 1] as RGBA8 (little-endian bytes r, g, b, a) with alpha 255.
std::uint32_t packed_colour(const glm::vec3& colour);

// The three corners of live face f of `mesh` in the buffer.
std::array<AppearanceVertex, 3> appearance_of_face(const rgb::Mesh& mesh, const SurfaceAppearance& appearance, rgb::FaceId f);

}  // namespace render
