#pragma once
// The CPU image of the surface vertex buffer (GL-free). Face slot f owns vertices 3f..3f+2, each
// carrying position, normal and a code (colour, face level, liveness), so a face change is a
// three-vertex range and the GPU buffer mirrors the core's slot arrays; dead slots are degenerate
// triangles that rasterise to nothing. Smooth normals are area-weighted averages of the incident
// face normals (split along infinitely sharp creases), so moving a vertex dirties the faces around
// its one-ring. With a SurfaceAppearance, a second array beside it holds each corner's colours,
// texture coordinate and texture, slot for slot; its colours and texture coordinates are the exact
// channels at the positions' level (surface_appearance.h), updated with the positions: a vertex
// whose position may have changed gets its colour again, a face rewritten its corners' UVs. On a cage
// with detail the code can carry the face's distance to the dense mesh too (set_detail_distance),
// measured again whenever its slot is written.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "render/camera.h"
#include "render/surface_appearance.h"
#include "rgb/mesh/handles.h"
#include "rgb/rules/face_type.h"

namespace rgb {
class Mesh;
}

namespace render {

class MeshChanges;

enum class PositionSource {
    Displayed,  // where the vertex is shown at its display level
    Limit,      // its limit-surface position where the core knows it, else the displayed position
};

struct SurfaceVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    std::uint32_t code = 0;

    friend bool operator==(const SurfaceVertex&, const SurfaceVertex&) = default;
};
static_assert(sizeof(SurfaceVertex) == 28, "the vertex layout in surface_buffer.cpp assumes packed floats");

// Layout of SurfaceVertex::code, mirrored in shaders/surface.frag.
inline constexpr std::uint32_t kCodeColourMask = 0x3u;
inline constexpr int kCodeLevelShift = 8;
inline constexpr std::uint32_t kCodeLiveBit = 1u << 16;
inline constexpr int kCodeDistanceShift = 24;  // the distance band (colour_map.h), with set_detail_distance

// Consecutive face slots [first, first + count).
struct SlotRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    friend bool operator==(const SlotRange&, const SlotRange&) = default;
};

class SurfaceGeometry {
public:
    explicit SurfaceGeometry(PositionSource source = PositionSource::Displayed);

    PositionSource source() const { return source_; }
    void set_source(PositionSource source) { source_ = source; }
    SurfaceGeometry(SurfaceGeometry&&) noexcept;
    SurfaceGeometry& operator=(SurfaceGeometry&&) noexcept;
    ~SurfaceGeometry();

    // What the faces look like (null: nothing but geometry); takes effect at the next rebuild.
    const std::shared_ptr<const SurfaceAppearance>& appearance() const { return appearance_; }
    void set_appearance(std::shared_ptr<const SurfaceAppearance> appearance);

    // Whether each face's code carries the band of its distance to the dense mesh (distance_band of
    // rgb::face_surface_error over distance_scale()), for Colouring::DetailDistance: on a mesh with
    // detail (elsewhere the bands stay 0). About 15 detail lookups per face written, so only while it
    // is shown. Takes effect at the next rebuild.
    bool detail_distance() const { return detail_distance_; }
    void set_detail_distance(bool on) { detail_distance_ = on; }
    // The length the bands are shares of (rgb::bounding_box_diagonal of the base mesh), while they are
    // measured; else nullopt.
    std::optional<double> distance_scale() const;

    // Recomputes every slot from the mesh.
    void rebuild(const rgb::Mesh& mesh);
    // Room for this many face and vertex slots, so that a growing mesh does not regrow the arrays
    // (a copy of hundreds of MB at millions of triangles) in whichever frame crosses the capacity.
    void reserve(std::size_t face_slots, std::size_t vertex_slots);
    // Recomputes the slots `changes` affects and returns them as sorted, coalesced ranges. The result
    // equals rebuild(mesh) bit for bit.
    std::vector<SlotRange> update(const rgb::Mesh& mesh, const MeshChanges& changes);
    // The same for a part of the lists of a MeshChanges that is not everything(): the lists cut
    // anywhere and the parts applied in turn leave the slots as update(mesh, changes) does, since a
    // slot that a later part affects is written again then. Meanwhile every slot written has its
    // corners where the mesh has them now (a new vertex whose part has not come yet would otherwise
    // sit at the origin, and thousands of such triangles in one cell make picking quadratic).
    std::vector<SlotRange> update_part(const rgb::Mesh& mesh, std::span<const rgb::FaceId> changed_faces,
                                       std::span<const rgb::VertexId> moved_vertices);

    std::span<const SurfaceVertex> vertices() const { return vertices_; }
    // One per vertex of vertices() with an appearance (since the last rebuild), else empty.
    std::span<const AppearanceVertex> appearance_vertices() const { return appearance_vertices_; }
    // The three positions of face slot f.
    std::array<glm::dvec3, 3> corners(rgb::FaceId f) const {
        return {glm::dvec3(vertices_[3 * f.idx].position), glm::dvec3(vertices_[3 * f.idx + 1].position),
                glm::dvec3(vertices_[3 * f.idx + 2].position)};
    }
    std::size_t face_slots() const { return vertices_.size() / 3; }
    // Live triangles of each colour and of each level (kept as slots are written, so reading them
    // costs nothing at any size), and the highest face level present.
    std::size_t triangles_of(rgb::Colour colour) const { return colour_counts_[static_cast<int>(colour)]; }
    std::size_t triangles_at(int level) const { return level_counts_[static_cast<std::size_t>(level)]; }
    int max_face_level() const;
    // The position shown for vertex slot v (live).
    const glm::vec3& position(rgb::VertexId v) const { return positions_[v.idx]; }
    // The positions of the live vertices, and their bounding sphere.
    std::vector<glm::vec3> live_positions(const rgb::Mesh& mesh) const;
    BoundingSphere bounds(const rgb::Mesh& mesh) const { return bounding_sphere(live_positions(mesh)); }

private:
    void resize(const rgb::Mesh& mesh);
    // update and update_part; `part`: position every corner of the slots written.
    std::vector<SlotRange> update_lists(const rgb::Mesh& mesh, std::span<const rgb::FaceId> changed_faces,
                                        std::span<const rgb::VertexId> moved_vertices, bool part);
    void update_position(const rgb::Mesh& mesh, rgb::VertexId v);
    void update_normal(const rgb::Mesh& mesh, rgb::VertexId v);
    // Corner i of f's normal: its vertex's, except at an infinitely sharp crease (rgb/rules/sharp_features.h),
    // where only the faces on f's side of the creases count, so that the shading breaks along it.
    glm::vec3 corner_normal(const rgb::Mesh& mesh, rgb::FaceId f, int i) const;
    // `alone`: the appearance's corners and the distance band too (a rebuild computes those for every
    // slot at once, in parallel).
    void write_slot(const rgb::Mesh& mesh, rgb::FaceId f, bool alone = true);
    // Every live slot's distance band, in parallel.
    void measure_all_distances(const rgb::Mesh& mesh);
    void count(std::uint32_t code, int delta);

    struct Marks {
        std::vector<std::uint32_t> stamps;
        std::uint32_t current = 0;
        void start();
        // False if the slot was marked already since start().
        bool mark(std::uint32_t slot);
    };

    PositionSource source_;
    bool detail_distance_ = false;
    struct DistanceMeasure;
    std::unique_ptr<DistanceMeasure> distance_;  // over the base mesh of the last rebuild, while measured
    std::shared_ptr<const SurfaceAppearance> appearance_;
    std::unique_ptr<AppearanceChannels> channels_;  // over the base mesh of the last rebuild
    std::vector<std::uint32_t> vertex_rgba_;         // by vertex slot, with vertex colours
    Marks vertex_marks_, face_marks_;
    std::vector<glm::vec3> positions_;  // by vertex slot
    std::vector<glm::vec3> normals_;    // by vertex slot
    std::vector<SurfaceVertex> vertices_;
    std::vector<AppearanceVertex> appearance_vertices_;
    std::array<std::size_t, 3> colour_counts_{};
    std::array<std::size_t, 256> level_counts_{};
};

}  // namespace render
