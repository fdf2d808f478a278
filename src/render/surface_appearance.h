#pragma once
// What the input file says about the surface's look, for the editor's material, vertex colour,
// texture checker and diffuse texture modes. Indexed by base face and base vertex (like
// rgbio::BaseAttributes, which the app converts: render does not parse mesh files), so refinement
// never changes it. A face of the adaptive mesh takes its material and texture from the base face it
// lies in; vertex colours and texture coordinates are the exact channels (rgb/values/vertex_channel.h,
// rgb/values/mesh_uvs.h) at the positions' level: the values a saved OBJ holds for the same mesh.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/texture_layers.h"
#include "rgb/mesh/handles.h"
#include "rgb/values/uv_layout.h"

namespace rgb {
class Mesh;
class UvEvaluator;
class VertexChannel;
}  // namespace rgb

namespace render {

// AppearanceVertex::texture beside a layer of SurfaceAppearance::textures: the face's material has
// no diffuse texture (it shows its colour), or one that could not be read (it shows the checker).
inline constexpr std::uint32_t kNoTexture = 0xffffffffu;
inline constexpr std::uint32_t kUnreadableTexture = 0xfffffffeu;

struct SurfaceAppearance {
    // Empty, or per base face: its material's diffuse colour (nullopt: no material).
    std::vector<std::optional<glm::vec3>> face_colours;
    std::vector<glm::dvec3> vertex_colours;  // empty, or per base vertex: the colour channel's values
    std::optional<rgb::UvChannel> uvs;       // the base mesh's texture coordinates
    // Empty, or per base face: the layer of `textures` that holds its material's diffuse texture, or
    // kNoTexture or kUnreadableTexture.
    std::vector<std::uint32_t> face_textures;
    TextureLayers textures;

    bool empty() const { return face_colours.empty() && vertex_colours.empty() && !uvs && face_textures.empty(); }
};

// Per vertex of the surface buffer, beside SurfaceVertex: colours as RGBA8 (alpha 255 where the
// file gives one, 0 where not), the texture coordinate (0, 0 where the file gives none) and the
// face's texture (SurfaceAppearance::face_textures; kNoTexture where the file gives none).
struct AppearanceVertex {
    std::uint32_t material_rgba = 0;
    std::uint32_t vertex_rgba = 0;
    glm::vec2 texcoord{0.0f};
    std::uint32_t texture = kNoTexture;

    friend bool operator==(const AppearanceVertex&, const AppearanceVertex&) = default;
};
static_assert(sizeof(AppearanceVertex) == 20, "the vertex layout in surface_buffer.cpp assumes packed fields");

// A colour in [0, 1] as RGBA8 (little-endian bytes r, g, b, a) with alpha 255.
std::uint32_t packed_colour(const glm::vec3& colour);

// An appearance's exact channels over one base mesh: what SurfaceGeometry keeps beside the mesh to
// give each vertex and corner its values as the mesh changes. It caches what it computes (not
// thread-safe) and must be made again for another base mesh (a retag).
class AppearanceChannels {
public:
    // `appearance` must outlive it; `base` is the mesh's base. Throws std::invalid_argument when the
    // appearance does not fit the base mesh.
    AppearanceChannels(std::shared_ptr<const rgb::BaseMesh> base, const SurfaceAppearance& appearance);
    ~AppearanceChannels();
    AppearanceChannels(const AppearanceChannels&) = delete;
    AppearanceChannels& operator=(const AppearanceChannels&) = delete;

    bool has_vertex_colours() const { return colours_ != nullptr; }
    // Every vertex slot's colour as RGBA8 (0 for dead slots), or empty without vertex colours: what
    // vertex_colour gives each, computed in parallel.
    std::vector<std::uint32_t> vertex_colours(const rgb::Mesh& mesh, bool limit) const;
    // Live vertex v's colour as RGBA8.
    std::uint32_t vertex_colour(const rgb::Mesh& mesh, rgb::VertexId v, bool limit);
    // The three corners of live face f, with its vertices' colours from `vertex_rgba` (by vertex
    // slot; empty without vertex colours); `limit`: limit texture coordinates instead of displayed ones.
    std::array<AppearanceVertex, 3> corners(const rgb::Mesh& mesh, rgb::FaceId f, const std::vector<std::uint32_t>& vertex_rgba,
                                            bool limit);
    // The same for every face slot into `out` (three per slot, dead slots AppearanceVertex{}), in
    // parallel: what a rebuild needs.
    void all_corners(const rgb::Mesh& mesh, const std::vector<std::uint32_t>& vertex_rgba, bool limit,
                     std::span<AppearanceVertex> out) const;

private:
    // corners() with texture coordinates from `uvs` (over layout_; null without texture coordinates),
    // or from `known` (by vertex slot, NaN where not known) where it has them.
    std::array<AppearanceVertex, 3> corners_from(const rgb::Mesh& mesh, rgb::FaceId f, const std::vector<std::uint32_t>& vertex_rgba,
                                                 bool limit, rgb::UvEvaluator* uvs, std::span<const glm::vec2> known = {}) const;
    // By vertex slot, the one UV of each vertex inside a base face (NaN for the others, whose UV
    // depends on the face), in parallel.
    std::vector<glm::vec2> inner_uvs(const rgb::Mesh& mesh, bool limit) const;

    std::shared_ptr<const rgb::BaseMesh> base_;
    const SurfaceAppearance& appearance_;
    std::unique_ptr<rgb::VertexChannel> colours_;
    std::unique_ptr<rgb::UvLayout> layout_;
    std::unique_ptr<rgb::UvEvaluator> uvs_;
};

}  // namespace render
