#include "render/surface_appearance.h"

#include <algorithm>
#include <cmath>

#include "rgb/face_location.h"
#include "rgb/mesh.h"
#include "rgb/mesh_uvs.h"
#include "rgb/uv_evaluator.h"
#include "rgb/vertex_channel.h"

namespace render {
namespace {

// The UV evaluator's values are only a cache: started afresh when this large, so that a long editing
// session keeps its memory bounded.
constexpr std::size_t kMaxCachedUvs = std::size_t(1) << 20;

std::uint32_t byte_of(float x) { return static_cast<std::uint32_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }

rgb::ChannelLevel channel_level(bool limit) { return limit ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed; }

template <class T>
const T* entry(const std::vector<T>& per_face, std::uint32_t b) {
    return per_face.empty() ? nullptr : &per_face[b];
}

}  // namespace

std::uint32_t packed_colour(const glm::vec3& colour) {
    return byte_of(colour.r) | byte_of(colour.g) << 8 | byte_of(colour.b) << 16 | 0xffu << 24;
}

AppearanceChannels::AppearanceChannels(std::shared_ptr<const rgb::BaseMesh> base, const SurfaceAppearance& appearance)
    : base_(std::move(base)), appearance_(appearance) {
    if (!appearance.vertex_colours.empty()) colours_ = std::make_unique<rgb::VertexChannel>(*base_, appearance.vertex_colours);
    if (appearance.uvs) layout_ = std::make_unique<rgb::UvLayout>(*base_, *appearance.uvs);
}

AppearanceChannels::~AppearanceChannels() = default;

std::vector<std::uint32_t> AppearanceChannels::vertex_colours(const rgb::Mesh& mesh, bool limit) const {
    if (!colours_) return {};
    const std::vector<glm::dvec3> values = rgb::vertex_channel_values(mesh, appearance_.vertex_colours, channel_level(limit));
    std::vector<std::uint32_t> packed(values.size(), 0);
    for (rgb::VertexId v : mesh.vertices()) packed[v.idx] = packed_colour(glm::vec3(values[v.idx]));
    return packed;
}

std::uint32_t AppearanceChannels::vertex_colour(const rgb::Mesh& mesh, rgb::VertexId v, bool limit) {
    return packed_colour(glm::vec3(colours_->value(mesh, v, channel_level(limit))));
}

std::array<AppearanceVertex, 3> AppearanceChannels::corners(const rgb::Mesh& mesh, rgb::FaceId f,
                                                            const std::vector<std::uint32_t>& vertex_rgba, bool limit) {
    std::array<AppearanceVertex, 3> out{};
    const std::uint32_t b = rgb::base_face_of(mesh, f);
    const std::optional<glm::vec3>* material = entry(appearance_.face_colours, b);
    const std::uint32_t* texture = entry(appearance_.face_textures, b);
    bool textured = false;
    if (layout_) {
        const std::vector<std::uint32_t>& untextured = layout_->channel().faces_without_uvs;
        textured = !std::binary_search(untextured.begin(), untextured.end(), b);
        if (!uvs_ || uvs_->cached_values() > kMaxCachedUvs) uvs_ = std::make_unique<rgb::UvEvaluator>(*base_, *layout_);
    }
    for (int c = 0; c < 3; ++c) {
        if (material && *material) out[c].material_rgba = packed_colour(**material);
        if (!vertex_rgba.empty()) out[c].vertex_rgba = vertex_rgba[mesh.face_vertices(f)[c].idx];
        if (textured) {
            out[c].texcoord = glm::vec2(limit ? rgb::limit_uv(mesh, *uvs_, f, c) : rgb::displayed_uv(mesh, *uvs_, f, c));
            // A texture needs texture coordinates: a face without them shows its material's colour.
            if (texture) out[c].texture = *texture;
        }
    }
    return out;
}

}  // namespace render
