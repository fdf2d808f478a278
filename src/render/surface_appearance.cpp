#include "render/surface_appearance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/support/parallel.h"
#include "rgb/values/mesh_uvs.h"
#include "rgb/values/uv_evaluator.h"
#include "rgb/values/vertex_channel.h"

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
    if (layout_ && (!uvs_ || uvs_->cached_values() > kMaxCachedUvs)) uvs_ = std::make_unique<rgb::UvEvaluator>(*base_, *layout_);
    return corners_from(mesh, f, vertex_rgba, limit, uvs_.get());
}

void AppearanceChannels::all_corners(const rgb::Mesh& mesh, const std::vector<std::uint32_t>& vertex_rgba, bool limit,
                                     std::span<AppearanceVertex> out) const {
    // Most corners belong to vertices inside a base face, which have one UV: evaluated once each.
    const std::vector<glm::vec2> known = inner_uvs(mesh, limit);
    // One evaluator per block (they cache, so cannot be shared), dropped with its values afterwards:
    // they would fill memory with the whole mesh's, where edits need few.
    rgb::parallel_for(mesh.face_capacity(), std::size_t(1) << 14, [&](std::size_t begin, std::size_t end) {
        std::unique_ptr<rgb::UvEvaluator> uvs;
        for (std::size_t i = begin; i < end; ++i) {
            const rgb::FaceId f(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(f)) {
                std::fill_n(out.begin() + static_cast<std::ptrdiff_t>(3 * i), 3, AppearanceVertex{});
                continue;
            }
            if (layout_ && (!uvs || uvs->cached_values() > kMaxCachedUvs)) {
                uvs = std::make_unique<rgb::UvEvaluator>(*base_, *layout_);
                uvs->reserve(std::min(kMaxCachedUvs, 2 * (end - i)));
            }
            std::ranges::copy(corners_from(mesh, f, vertex_rgba, limit, uvs.get(), known), out.begin() + static_cast<std::ptrdiff_t>(3 * i));
        }
    });
}

std::vector<glm::vec2> AppearanceChannels::inner_uvs(const rgb::Mesh& mesh, bool limit) const {
    if (!layout_) return {};
    std::vector<glm::vec2> uvs(mesh.vertex_capacity(), glm::vec2(std::numeric_limits<float>::quiet_NaN()));
    rgb::parallel_for(mesh.vertex_capacity(), std::size_t(1) << 14, [&](std::size_t begin, std::size_t end) {
        std::unique_ptr<rgb::UvEvaluator> evaluator;
        for (std::size_t i = begin; i < end; ++i) {
            const rgb::VertexId v(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(v) || rgb::on_base_edge_or_vertex(mesh.address(v))) continue;
            if (!evaluator || evaluator->cached_values() > kMaxCachedUvs) {
                evaluator = std::make_unique<rgb::UvEvaluator>(*base_, *layout_);
                evaluator->reserve(std::min(kMaxCachedUvs, 2 * (end - i)));
            }
            // Any face of v gives its UV; the one its halfedge leads to.
            const rgb::FaceId f = rgb::Mesh::face(mesh.vertex_halfedge(v));
            const auto& corners = mesh.face_vertices(f);
            const int c = static_cast<int>(std::ranges::find(corners, v) - corners.begin());
            uvs[i] = glm::vec2(limit ? rgb::limit_uv(mesh, *evaluator, f, c) : rgb::displayed_uv(mesh, *evaluator, f, c));
        }
    });
    return uvs;
}

std::array<AppearanceVertex, 3> AppearanceChannels::corners_from(const rgb::Mesh& mesh, rgb::FaceId f,
                                                                 const std::vector<std::uint32_t>& vertex_rgba, bool limit,
                                                                 rgb::UvEvaluator* uvs, std::span<const glm::vec2> known) const {
    std::array<AppearanceVertex, 3> out{};
    const std::uint32_t b = rgb::base_face_of(mesh, f);
    const std::optional<glm::vec3>* material = entry(appearance_.face_colours, b);
    const std::uint32_t* texture = entry(appearance_.face_textures, b);
    bool textured = false;
    if (uvs) {
        const std::vector<std::uint32_t>& untextured = layout_->channel().faces_without_uvs;
        textured = !std::binary_search(untextured.begin(), untextured.end(), b);
    }
    for (int c = 0; c < 3; ++c) {
        if (material && *material) out[c].material_rgba = packed_colour(**material);
        if (!vertex_rgba.empty()) out[c].vertex_rgba = vertex_rgba[mesh.face_vertices(f)[c].idx];
        if (textured) {
            const std::uint32_t v = mesh.face_vertices(f)[c].idx;
            if (!known.empty() && !std::isnan(known[v].x)) out[c].texcoord = known[v];
            else out[c].texcoord = glm::vec2(limit ? rgb::limit_uv(mesh, *uvs, f, c) : rgb::displayed_uv(mesh, *uvs, f, c));
            // A texture needs texture coordinates: a face without them shows its material's colour.
            if (texture) out[c].texture = *texture;
        }
    }
    return out;
}

}  // namespace render
