#pragma once
// A spatial index over the displayed triangles, for picking: each face slot of a
// render::SurfaceGeometry sits in the cells of a sparse grid whose cell size suits it (one grid per
// power of two of cell size, a triangle in the grid whose cells are at least twice its size, so in
// at most eight cells and mostly in one to four). A ray walks each grid that holds triangles, coarse grids first, block by block
// (8x8x8 cells, empty blocks skipped) and then cell by cell, and stops once it is past the nearest
// hit so far: the cost follows the occupied cells the ray crosses, not the triangles. Updating costs
// in proportion to the slots that changed.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "app/cell_table.h"
#include "app/surface_picking.h"
#include "render/surface_geometry.h"

namespace rgb {
class Mesh;
}

namespace app {

class SurfaceIndex {
public:
    // Indexes every live slot. Displayed positions (and limits) lie in the convex hull of the base
    // mesh, so its bounding box holds the grids.
    void rebuild(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry);
    // Re-places the slots in `ranges` (what SurfaceGeometry::update returned).
    void update(const render::SurfaceGeometry& geometry, std::span<const render::SlotRange> ranges);
    // Room for this many face slots (as SurfaceGeometry::reserve).
    void reserve(std::size_t face_slots);

    // The nearest front-facing triangle along the ray.
    std::optional<SurfaceHit> pick(const render::SurfaceGeometry& geometry, const Ray& ray) const;

    std::size_t memory_bytes() const;

private:
    // Where a slot is, in one word: the key of its lowest cell (level, x, y, z) and in bits 59-61,
    // per axis, whether it reaches into the next cell; kNowhere for a dead slot.
    using Placement = std::uint64_t;
    static constexpr Placement kNowhere = ~Placement{0};
    struct Ref {
        std::uint32_t slot;
        std::uint32_t next;
    };

    Placement placement(const render::SurfaceGeometry& geometry, std::uint32_t slot) const;
    void place(std::uint32_t slot, const Placement& where);
    // The key of the block of cells holding `cell` (a cell key of the grid whose cells are blocks).
    static std::uint64_t block_of(std::uint64_t cell);
    void insert(std::uint64_t cell, std::uint32_t slot);
    void remove(std::uint64_t cell, std::uint32_t slot);
    void walk_level(const render::SurfaceGeometry& geometry, const Ray& ray, int level, double t_enter, double t_exit,
                    std::optional<SurfaceHit>& best) const;

    glm::dvec3 origin_{0.0};
    double finest_cell_ = 1.0;
    std::vector<Placement> placements_;  // per face slot
    std::array<std::size_t, 32> per_level_{};
    CellTable cells_;        // cell key -> first Ref
    CellTable blocks_;       // block key -> Refs in its cells
    std::vector<Ref> refs_;  // singly linked lists per cell, free ones chained from free_ref_
    std::uint32_t free_ref_ = CellTable::kNone;
};

}  // namespace app
