#include "render/surface_geometry.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "render/colour_map.h"
#include "render/mesh_changes.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/support/parallel.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/surface_error.h"

namespace render {
namespace {

// Dirty slots closer than this are uploaded as one range: a few wasted bytes are cheaper than a
// separate glBufferSubData call.
constexpr std::uint32_t kCoalesceGap = 8;

template <class Fn>
void for_each_face_around(const rgb::Mesh& mesh, rgb::VertexId v, Fn&& fn) {
    const rgb::HalfedgeId start = mesh.vertex_halfedge(v);
    if (!start.valid()) return;
    rgb::HalfedgeId h = start;
    do {
        fn(rgb::Mesh::face(h));
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
}


std::vector<SlotRange> coalesce(const std::vector<rgb::FaceId>& sorted_faces) {
    std::vector<SlotRange> ranges;
    for (rgb::FaceId f : sorted_faces) {
        if (!ranges.empty() && f.idx <= ranges.back().first + ranges.back().count + kCoalesceGap)
            ranges.back().count = f.idx + 1 - ranges.back().first;
        else
            ranges.push_back({f.idx, 1});
    }
    return ranges;
}

// Twice the area times the unit normal, from the shown positions.
glm::dvec3 area_normal(const rgb::Mesh& mesh, const std::vector<glm::vec3>& positions, rgb::FaceId f) {
    const auto& c = mesh.face_vertices(f);
    const glm::dvec3 p0 = positions[c[0].idx];
    return glm::cross(glm::dvec3(positions[c[1].idx]) - p0, glm::dvec3(positions[c[2].idx]) - p0);
}

glm::vec3 unit_or_up(const glm::dvec3& sum) {
    const double length = glm::length(sum);
    return length > 0.0 ? glm::vec3(sum / length) : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Whether the interior edge of h lies on an infinitely sharp base edge: the surface folds there.
bool creased(const rgb::Mesh& mesh, rgb::HalfedgeId h) {
    const auto on = rgb::base_edge_between(mesh.base(), mesh.address(mesh.from_vertex(h)), mesh.address(mesh.to_vertex(h)));
    return on && mesh.base().edge_sharpness(*on) >= rgb::kInfiniteSharpness;
}

std::uint32_t face_code(const rgb::Mesh& mesh, rgb::FaceId f) {
    return static_cast<std::uint32_t>(mesh.colour(f)) | (static_cast<std::uint32_t>(mesh.level(f)) << kCodeLevelShift) |
           kCodeLiveBit;
}

// The code bits of live face f's distance band, its largest departure from the dense mesh over `diagonal`.
std::uint32_t distance_bits(const rgb::Mesh& mesh, rgb::FaceId f, rgb::HierarchyEvaluator& evaluator, double diagonal) {
    const double error = rgb::face_surface_error(mesh, evaluator, f).max_error;
    return static_cast<std::uint32_t>(distance_band(error / diagonal)) << kCodeDistanceShift;
}

}  // namespace

struct SurfaceGeometry::DistanceMeasure {
    explicit DistanceMeasure(std::shared_ptr<const rgb::BaseMesh> over)
        : base(std::move(over)), evaluator(*base), diagonal(rgb::bounding_box_diagonal(*base)) {}
    std::shared_ptr<const rgb::BaseMesh> base;  // the evaluator's
    rgb::HierarchyEvaluator evaluator;
    double diagonal;
};

SurfaceGeometry::SurfaceGeometry(PositionSource source) : source_(source) {}
SurfaceGeometry::SurfaceGeometry(SurfaceGeometry&&) noexcept = default;
SurfaceGeometry& SurfaceGeometry::operator=(SurfaceGeometry&&) noexcept = default;
SurfaceGeometry::~SurfaceGeometry() = default;

void SurfaceGeometry::set_appearance(std::shared_ptr<const SurfaceAppearance> appearance) {
    channels_.reset();
    vertex_rgba_.clear();
    appearance_ = std::move(appearance);
}

std::optional<double> SurfaceGeometry::distance_scale() const {
    if (!distance_) return std::nullopt;
    return distance_->diagonal;
}

int SurfaceGeometry::max_face_level() const {
    for (int level = static_cast<int>(level_counts_.size()) - 1; level > 0; --level)
        if (level_counts_[static_cast<std::size_t>(level)] > 0) return level;
    return 0;
}

std::vector<glm::vec3> SurfaceGeometry::live_positions(const rgb::Mesh& mesh) const {
    std::vector<glm::vec3> live;
    live.reserve(mesh.num_vertices());
    for (rgb::VertexId v : mesh.vertices()) live.push_back(positions_[v.idx]);
    return live;
}

void SurfaceGeometry::resize(const rgb::Mesh& mesh) {
    positions_.resize(mesh.vertex_capacity());
    normals_.resize(mesh.vertex_capacity());
    if (channels_ && channels_->has_vertex_colours()) vertex_rgba_.resize(mesh.vertex_capacity());
    const std::size_t slots = mesh.face_capacity();
    for (std::size_t i = slots * 3; i < vertices_.size(); i += 3) count(vertices_[i].code, -1);
    vertices_.resize(slots * 3);
    appearance_vertices_.resize(channels_ ? slots * 3 : 0);
}

void SurfaceGeometry::reserve(std::size_t face_slots, std::size_t vertex_slots) {
    positions_.reserve(vertex_slots);
    normals_.reserve(vertex_slots);
    vertices_.reserve(3 * face_slots);
    if (appearance_) appearance_vertices_.reserve(3 * face_slots);
}

void SurfaceGeometry::update_position(const rgb::Mesh& mesh, rgb::VertexId v) {
    const glm::dvec3 p = source_ == PositionSource::Limit
                             ? rgb::limit_position(mesh, v)
                             : rgb::displayed_position(mesh, v);
    positions_[v.idx] = glm::vec3(p);
}

// In double: the cross products grow with the square of the scale, and leave float's range for
// meshes far from unit size (1e10: overflow, 1e-20: underflow).
void SurfaceGeometry::update_normal(const rgb::Mesh& mesh, rgb::VertexId v) {
    glm::dvec3 sum(0.0);
    for_each_face_around(mesh, v, [&](rgb::FaceId f) { sum += area_normal(mesh, positions_, f); });
    normals_[v.idx] = unit_or_up(sum);
}

glm::vec3 SurfaceGeometry::corner_normal(const rgb::Mesh& mesh, rgb::FaceId f, int i) const {
    const rgb::VertexId v = mesh.face_vertices(f)[i];
    // Only a base vertex or a vertex on a base edge can lie on a crease.
    if (mesh.base().sharp_features().edges.empty() || !rgb::on_base_edge_or_vertex(mesh.address(v))) return normals_[v.idx];
    const rgb::HalfedgeId start = rgb::Mesh::halfedge(f, i);  // leaves v
    glm::dvec3 sum = area_normal(mesh, positions_, f);
    // Counter-clockwise across v's edge in the previous face's slot, clockwise across start's edge.
    for (rgb::HalfedgeId h = start; !creased(mesh, rgb::Mesh::prev(h));) {
        h = mesh.ccw_rotated(h);
        if (!h.valid()) break;
        if (h == start) return normals_[v.idx];  // all the way round: no crease through v
        sum += area_normal(mesh, positions_, rgb::Mesh::face(h));
    }
    for (rgb::HalfedgeId h = start; !creased(mesh, h);) {
        h = mesh.cw_rotated(h);
        if (!h.valid()) break;
        sum += area_normal(mesh, positions_, rgb::Mesh::face(h));
    }
    return unit_or_up(sum);
}

void SurfaceGeometry::count(std::uint32_t code, int delta) {
    if ((code & kCodeLiveBit) == 0) return;
    colour_counts_[code & kCodeColourMask] += static_cast<std::size_t>(delta);
    level_counts_[(code >> kCodeLevelShift) & 0xffu] += static_cast<std::size_t>(delta);
}

void SurfaceGeometry::write_slot(const rgb::Mesh& mesh, rgb::FaceId f, bool alone) {
    SurfaceVertex* slot = &vertices_[3 * static_cast<std::size_t>(f.idx)];
    count(slot[0].code, -1);
    AppearanceVertex* look = channels_ && alone ? &appearance_vertices_[3 * static_cast<std::size_t>(f.idx)] : nullptr;
    if (!mesh.is_live(f)) {
        std::fill(slot, slot + 3, SurfaceVertex{});
        if (look) std::fill(look, look + 3, AppearanceVertex{});
        return;
    }
    std::uint32_t code = face_code(mesh, f);
    if (distance_ && alone) code |= distance_bits(mesh, f, distance_->evaluator, distance_->diagonal);
    const auto& corners = mesh.face_vertices(f);
    for (int i = 0; i < 3; ++i) slot[i] = {positions_[corners[i].idx], corner_normal(mesh, f, i), code};
    if (look) std::ranges::copy(channels_->corners(mesh, f, vertex_rgba_, source_ == PositionSource::Limit), look);
    count(code, +1);
}

void SurfaceGeometry::rebuild(const rgb::Mesh& mesh) {
    vertices_.clear();
    appearance_vertices_.clear();
    colour_counts_ = {};
    level_counts_ = {};
    // The base mesh may be another one (a retag): the channels and the distance measure start afresh over it.
    channels_ = appearance_ ? std::make_unique<AppearanceChannels>(mesh.shared_base(), *appearance_) : nullptr;
    distance_ = detail_distance_ && mesh.base().detail() ? std::make_unique<DistanceMeasure>(mesh.shared_base()) : nullptr;
    // All colours at once, in parallel (the values update() gives single vertices).
    vertex_rgba_ = channels_ ? channels_->vertex_colours(mesh, source_ == PositionSource::Limit) : std::vector<std::uint32_t>();
    resize(mesh);
    for (rgb::VertexId v : mesh.vertices()) update_position(mesh, v);
    for (rgb::VertexId v : mesh.vertices()) update_normal(mesh, v);
    for (std::uint32_t f = 0; f < mesh.face_capacity(); ++f) write_slot(mesh, rgb::FaceId(f), false);
    if (channels_) channels_->all_corners(mesh, vertex_rgba_, source_ == PositionSource::Limit, appearance_vertices_);
    if (distance_) measure_all_distances(mesh);
}

void SurfaceGeometry::measure_all_distances(const rgb::Mesh& mesh) {
    rgb::parallel_for(mesh.face_capacity(), std::size_t(1) << 12, [&](std::size_t begin, std::size_t end) {
        rgb::HierarchyEvaluator evaluator(mesh.base());  // it caches, so one per block
        for (std::size_t i = begin; i < end; ++i) {
            const rgb::FaceId f(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(f)) continue;
            const std::uint32_t bits = distance_bits(mesh, f, evaluator, distance_->diagonal);
            for (std::size_t c = 0; c < 3; ++c) vertices_[3 * i + c].code |= bits;
        }
    });
}

// Marks over slots for one update, so that each vertex and face is handled once (the change lists
// name most of them several times) without sorting them.
bool SurfaceGeometry::Marks::mark(std::uint32_t slot) {
    if (slot >= stamps.size()) stamps.resize(std::max<std::size_t>(slot + 1, 2 * stamps.size()), 0);
    if (stamps[slot] == current) return false;
    stamps[slot] = current;
    return true;
}

void SurfaceGeometry::Marks::start() {
    if (++current == 0) {
        std::fill(stamps.begin(), stamps.end(), 0);
        current = 1;
    }
}

std::vector<SlotRange> SurfaceGeometry::update(const rgb::Mesh& mesh, const MeshChanges& changes) {
    if (changes.everything()) {
        rebuild(mesh);
        return {SlotRange{0, static_cast<std::uint32_t>(face_slots())}};
    }
    return update_lists(mesh, changes.changed_faces(), changes.moved_vertices(), false);
}

std::vector<SlotRange> SurfaceGeometry::update_part(const rgb::Mesh& mesh, std::span<const rgb::FaceId> changed_faces,
                                                    std::span<const rgb::VertexId> moved_vertices) {
    return update_lists(mesh, changed_faces, moved_vertices, true);
}

std::vector<SlotRange> SurfaceGeometry::update_lists(const rgb::Mesh& mesh, std::span<const rgb::FaceId> changed_faces,
                                                     std::span<const rgb::VertexId> moved_vertices, bool part) {
    resize(mesh);
    vertex_marks_.start();
    std::vector<rgb::VertexId> moved;
    for (rgb::VertexId v : moved_vertices)
        if (mesh.is_live(v) && vertex_marks_.mark(v.idx)) moved.push_back(v);
    for (rgb::VertexId v : moved) update_position(mesh, v);
    // A colour is at its vertex's display level, as the position.
    if (channels_ && channels_->has_vertex_colours())
        for (rgb::VertexId v : moved) vertex_rgba_[v.idx] = channels_->vertex_colour(mesh, v, source_ == PositionSource::Limit);

    // A vertex's normal depends on its one-ring's positions.
    vertex_marks_.start();
    std::vector<rgb::VertexId> renormal;
    for (rgb::VertexId v : moved)
        if (vertex_marks_.mark(v.idx)) renormal.push_back(v);
    for (rgb::VertexId v : moved)
        for_each_face_around(mesh, v, [&](rgb::FaceId f) {
            for (rgb::VertexId u : mesh.face_vertices(f))
                if (vertex_marks_.mark(u.idx)) renormal.push_back(u);
        });
    for (rgb::VertexId v : renormal) update_normal(mesh, v);

    face_marks_.start();
    std::vector<rgb::FaceId> dirty;
    auto add_dirty = [&](rgb::FaceId f) {
        if (f.idx < mesh.face_capacity() && face_marks_.mark(f.idx)) dirty.push_back(f);
    };
    for (rgb::FaceId f : changed_faces) add_dirty(f);
    for (rgb::VertexId v : renormal) for_each_face_around(mesh, v, add_dirty);
    std::sort(dirty.begin(), dirty.end());
    if (part) {
        vertex_marks_.start();
        for (rgb::VertexId v : moved) vertex_marks_.mark(v.idx);
        for (rgb::FaceId f : dirty)
            if (mesh.is_live(f))
                for (rgb::VertexId u : mesh.face_vertices(f))
                    if (vertex_marks_.mark(u.idx)) update_position(mesh, u);
    }
    for (rgb::FaceId f : dirty) write_slot(mesh, f);
    return coalesce(dirty);
}

}  // namespace render
