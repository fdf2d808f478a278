#include "render/surface_appearance.h"

#include <algorithm>
#include <cmath>

#include "rgb/face_location.h"
#include "rgb/mesh.h"

namespace render {
namespace {

std::uint32_t byte_of(float x) { return static_cast<std::uint32_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }

// The barycentric coordinates of v in base face `base_face` (every vertex of a face lies on the
// closed triangle of the face's base face).
glm::vec3 weights_in(const rgb::Mesh& mesh, rgb::VertexId v, std::uint32_t base_face) {
    const rgb::SurfacePoint p = *rgb::in_face(mesh.base(), mesh.address(v), base_face);
    const float scale = std::ldexp(1.0f, -p.level);
    return {static_cast<float>(p.a[0]) * scale, static_cast<float>(p.a[1]) * scale, static_cast<float>(p.a[2]) * scale};
}

template <class T>
T interpolate(const glm::vec3& w, const T& a, const T& b, const T& c) {
    return w.x * a + w.y * b + w.z * c;
}

}  // namespace

std::uint32_t packed_colour(const glm::vec3& colour) {
    return byte_of(colour.r) | byte_of(colour.g) << 8 | byte_of(colour.b) << 16 | 0xffu << 24;
}

std::array<AppearanceVertex, 3> appearance_of_face(const rgb::Mesh& mesh, const SurfaceAppearance& appearance, rgb::FaceId f) {
    std::array<AppearanceVertex, 3> out{};
    const std::uint32_t b = rgb::base_face_of(mesh, f);
    const rgb::Triangle& corners = mesh.base().face(b);
    const glm::vec3* material =
        appearance.face_colours.empty() || !appearance.face_colours[b] ? nullptr : &*appearance.face_colours[b];
    const std::array<glm::vec2, 3>* texcoords =
        appearance.corner_texcoords.empty() || !appearance.corner_texcoords[b] ? nullptr : &*appearance.corner_texcoords[b];
    for (int c = 0; c < 3; ++c) {
        const glm::vec3 w = weights_in(mesh, mesh.face_vertices(f)[c], b);
        if (material) out[c].material_rgba = packed_colour(*material);
        if (!appearance.vertex_colours.empty())
            out[c].vertex_rgba = packed_colour(interpolate(w, appearance.vertex_colours[corners[0]], appearance.vertex_colours[corners[1]],
                                                           appearance.vertex_colours[corners[2]]));
        if (texcoords) out[c].texcoord = interpolate(w, (*texcoords)[0], (*texcoords)[1], (*texcoords)[2]);
    }
    return out;
}

}  // namespace render
