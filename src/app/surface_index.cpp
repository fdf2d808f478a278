#include "app/surface_index.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "rgb/mesh/mesh.h"

namespace app {
namespace {

// Cells per axis of the finest grid over the base mesh's box; coordinates take 18 bits.
constexpr int kCoordinateBits = 18;
constexpr std::int64_t kFinestCells = std::int64_t{1} << (kCoordinateBits - 1);
constexpr int kLevels = kCoordinateBits;  // the coarsest grid is one cell
constexpr int kReachShift = 59;
// Cells per axis of a block: a walk skips a block whose cells are all empty in one step.
constexpr std::int64_t kBlockCells = 8;
// Displayed positions are floats: a margin keeps their rounding inside the box.
constexpr double kMargin = 1e-3;

std::uint64_t cell_key(int level, std::int64_t x, std::int64_t y, std::int64_t z) {
    return (std::uint64_t(level) << (3 * kCoordinateBits)) | (std::uint64_t(x) << (2 * kCoordinateBits)) |
           (std::uint64_t(y) << kCoordinateBits) | std::uint64_t(z);
}

int key_level(std::uint64_t key) { return static_cast<int>((key >> (3 * kCoordinateBits)) & 31u); }

std::int64_t cells_at(int level) { return std::max<std::int64_t>(kFinestCells >> level, 1); }

}  // namespace

void SurfaceIndex::rebuild(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : mesh.base().positions()) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    double side = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    if (!(side > 0.0)) side = std::max(1.0, std::abs(lo.x));
    origin_ = lo - kMargin * side;
    finest_cell_ = side * (1.0 + 2.0 * kMargin) / static_cast<double>(kFinestCells);
    placements_.assign(geometry.face_slots(), kNowhere);
    per_level_ = {};
    cells_.clear();
    blocks_.clear();
    refs_.clear();
    free_ref_ = CellTable::kNone;
    for (std::uint32_t slot = 0; slot < geometry.face_slots(); ++slot) place(slot, placement(geometry, slot));
}

void SurfaceIndex::reserve(std::size_t face_slots) {
    placements_.reserve(face_slots);
    refs_.reserve(2 * face_slots);  // a triangle sits in one to four cells, mostly one or two
}

void SurfaceIndex::update(const render::SurfaceGeometry& geometry, std::span<const render::SlotRange> ranges) {
    const auto slots = static_cast<std::uint32_t>(geometry.face_slots());
    for (auto slot = static_cast<std::uint32_t>(placements_.size()); slot-- > slots;) place(slot, kNowhere);
    placements_.resize(slots, kNowhere);
    for (const render::SlotRange& range : ranges)
        for (std::uint32_t slot = range.first; slot < range.first + range.count && slot < slots; ++slot)
            if (const Placement where = placement(geometry, slot); where != placements_[slot]) place(slot, where);
}

SurfaceIndex::Placement SurfaceIndex::placement(const render::SurfaceGeometry& geometry, std::uint32_t slot) const {
    if ((geometry.vertices()[3 * std::size_t{slot}].code & render::kCodeLiveBit) == 0) return kNowhere;
    const auto corners = geometry.corners(rgb::FaceId(slot));
    const glm::dvec3 lo = glm::min(corners[0], glm::min(corners[1], corners[2])) - origin_;
    const glm::dvec3 hi = glm::max(corners[0], glm::max(corners[1], corners[2])) - origin_;
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    // The finest grid whose cells are at least twice the triangle's size: it then spans two cells
    // per axis at most (one more level if rounding says otherwise). Cells of just its size would
    // hold fewer triangles each but put each in more cells, which costs more to keep.
    int level = 2.0 * extent > finest_cell_ ? std::min(static_cast<int>(std::ceil(std::log2(2.0 * extent / finest_cell_))), kLevels) : 0;
    for (;; ++level) {
        const double cell = std::ldexp(finest_cell_, level);
        const std::int64_t top = cells_at(level) - 1;
        std::array<std::int64_t, 3> first{}, last{};
        for (int a = 0; a < 3; ++a) {
            first[a] = std::clamp(static_cast<std::int64_t>(std::floor(lo[a] / cell)), std::int64_t{0}, top);
            last[a] = std::clamp(static_cast<std::int64_t>(std::floor(hi[a] / cell)), std::int64_t{0}, top);
        }
        if (level < kLevels && (last[0] - first[0] > 1 || last[1] - first[1] > 1 || last[2] - first[2] > 1)) continue;
        std::uint64_t reach = 0;
        for (int a = 0; a < 3; ++a) reach |= std::uint64_t(last[a] > first[a]) << a;
        return cell_key(level, first[0], first[1], first[2]) | (reach << kReachShift);
    }
}

void SurfaceIndex::place(std::uint32_t slot, const Placement& where) {
    for (int pass = 0; pass < 2; ++pass) {
        const Placement p = pass == 0 ? placements_[slot] : where;
        if (p == kNowhere) continue;
        const std::uint64_t key = p & ((std::uint64_t{1} << kReachShift) - 1);
        const std::uint64_t reach = p >> kReachShift;
        for (std::uint64_t d = 0; d < 8; ++d) {
            if ((d & ~reach) != 0) continue;
            const std::uint64_t cell = key + ((d & 1) << (2 * kCoordinateBits)) + (((d >> 1) & 1) << kCoordinateBits) + ((d >> 2) & 1);
            if (pass == 0) remove(cell, slot);
            else insert(cell, slot);
        }
        per_level_[static_cast<std::size_t>(key_level(key))] += pass == 0 ? std::size_t(-1) : 1;
    }
    placements_[slot] = where;
}

std::uint64_t SurfaceIndex::block_of(std::uint64_t cell) {
    const std::uint64_t mask = (std::uint64_t{1} << kCoordinateBits) - 1;
    const int shift = std::countr_zero(static_cast<unsigned>(kBlockCells));
    const std::uint64_t x = (cell >> (2 * kCoordinateBits)) & mask, y = (cell >> kCoordinateBits) & mask, z = cell & mask;
    return cell_key(key_level(cell), static_cast<std::int64_t>(x >> shift), static_cast<std::int64_t>(y >> shift),
                    static_cast<std::int64_t>(z >> shift));
}

void SurfaceIndex::insert(std::uint64_t cell, std::uint32_t slot) {
    blocks_.update(block_of(cell), [](std::uint32_t in_block) { return in_block == CellTable::kNone ? 1 : in_block + 1; });
    std::uint32_t ref = free_ref_;
    if (ref != CellTable::kNone) {
        free_ref_ = refs_[ref].next;
    } else {
        ref = static_cast<std::uint32_t>(refs_.size());
        refs_.emplace_back();
    }
    cells_.update(cell, [&](std::uint32_t head) {
        refs_[ref] = {slot, head};
        return ref;
    });
}

void SurfaceIndex::remove(std::uint64_t cell, std::uint32_t slot) {
    cells_.update(cell, [&](std::uint32_t head) {
        for (std::uint32_t* link = &head; *link != CellTable::kNone; link = &refs_[*link].next) {
            if (refs_[*link].slot != slot) continue;
            const std::uint32_t ref = *link;
            *link = refs_[ref].next;
            refs_[ref].next = free_ref_;
            free_ref_ = ref;
            break;
        }
        return head;
    });
    blocks_.update(block_of(cell), [](std::uint32_t in_block) { return in_block == 1 ? CellTable::kNone : in_block - 1; });
}

std::optional<SurfaceHit> SurfaceIndex::pick(const render::SurfaceGeometry& geometry, const Ray& ray) const {
    // The part of the ray inside the box (slabs).
    const double side = finest_cell_ * static_cast<double>(kFinestCells);
    double t_enter = 0.0, t_exit = std::numeric_limits<double>::max();
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a] - origin_[a];
        if (ray.direction[a] == 0.0) {
            if (o < 0.0 || o > side) return std::nullopt;
            continue;
        }
        const double t0 = -o / ray.direction[a], t1 = (side - o) / ray.direction[a];
        t_enter = std::max(t_enter, std::min(t0, t1));
        t_exit = std::min(t_exit, std::max(t0, t1));
    }
    std::optional<SurfaceHit> best;
    if (t_enter > t_exit) return best;
    // Coarse grids first: they are short walks and bound the fine ones.
    for (int level = kLevels; level >= 0; --level)
        if (per_level_[static_cast<std::size_t>(level)] > 0) walk_level(geometry, ray, level, t_enter, t_exit, best);
    return best;
}

// Amanatides and Woo's walk through the cells (of size `cell`, coordinates within [lo, hi]) that
// the ray crosses between t0 and t1: visit(x, y, z, t_in, t_out) for each, in order, until it
// returns false.
template <class Visit>
void walk_cells(const Ray& ray, const glm::dvec3& origin, double cell, const std::array<std::int64_t, 3>& lo,
                const std::array<std::int64_t, 3>& hi, double t0, double t1, Visit&& visit) {
    std::array<std::int64_t, 3> c{}, step{};
    std::array<double, 3> t_next{}, t_delta{};
    const glm::dvec3 entry = ray.origin + t0 * ray.direction - origin;
    for (int a = 0; a < 3; ++a) {
        c[a] = std::clamp(static_cast<std::int64_t>(std::floor(entry[a] / cell)), lo[a], hi[a]);
        const double d = ray.direction[a];
        step[a] = d > 0.0 ? 1 : -1;
        t_delta[a] = d != 0.0 ? cell / std::abs(d) : std::numeric_limits<double>::infinity();
        const double boundary = origin[a] + static_cast<double>(c[a] + (d > 0.0 ? 1 : 0)) * cell;
        t_next[a] = d != 0.0 ? (boundary - ray.origin[a]) / d : std::numeric_limits<double>::infinity();
    }
    for (double t = t0; t <= t1;) {
        const int a = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
        if (!visit(c[0], c[1], c[2], t, std::min(t_next[a], t1))) return;
        t = t_next[a];
        c[a] += step[a];
        if (c[a] < lo[a] || c[a] > hi[a]) return;
        t_next[a] += t_delta[a];
    }
}

// One grid: blocks of cells first, skipping the empty ones, then the cells of each occupied block,
// until past the best hit.
void SurfaceIndex::walk_level(const render::SurfaceGeometry& geometry, const Ray& ray, int level, double t_enter, double t_exit,
                              std::optional<SurfaceHit>& best) const {
    const double cell = std::ldexp(finest_cell_, level);
    const std::int64_t cells = cells_at(level);
    const std::int64_t blocks = (cells + kBlockCells - 1) / kBlockCells;
    auto before_best = [&](double t) { return !best || t <= best->distance; };
    walk_cells(ray, origin_, cell * kBlockCells, {0, 0, 0}, {blocks - 1, blocks - 1, blocks - 1}, t_enter, t_exit,
               [&](std::int64_t bx, std::int64_t by, std::int64_t bz, double t_in, double t_out) {
                   if (!before_best(t_in)) return false;
                   if (blocks_.find(cell_key(level, bx, by, bz)) == CellTable::kNone) return true;
                   const std::array<std::int64_t, 3> lo{bx * kBlockCells, by * kBlockCells, bz * kBlockCells};
                   const std::array<std::int64_t, 3> hi{std::min(lo[0] + kBlockCells, cells) - 1, std::min(lo[1] + kBlockCells, cells) - 1,
                                                        std::min(lo[2] + kBlockCells, cells) - 1};
                   walk_cells(ray, origin_, cell, lo, hi, t_in, t_out, [&](std::int64_t x, std::int64_t y, std::int64_t z, double t, double) {
                       if (!before_best(t)) return false;
                       for (std::uint32_t ref = cells_.find(cell_key(level, x, y, z)); ref != CellTable::kNone; ref = refs_[ref].next) {
                           const rgb::FaceId f(refs_[ref].slot);
                           const std::optional<double> distance = front_hit(ray, geometry.corners(f));
                           if (distance && (!best || *distance < best->distance))
                               best = SurfaceHit{f, ray.origin + *distance * ray.direction, *distance};
                       }
                       return true;
                   });
                   return true;
               });
}

std::size_t SurfaceIndex::memory_bytes() const {
    return placements_.capacity() * sizeof(Placement) + refs_.capacity() * sizeof(Ref) + cells_.memory_bytes() + blocks_.memory_bytes();
}

}  // namespace app
