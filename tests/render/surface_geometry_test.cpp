// The CPU image of the vertex buffer: incremental updates driven by the observer must give exactly
// what a full rebuild gives, and touch only the neighbourhood of an edit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <span>
#include <vector>

#include "render/colour_map.h"
#include "render/mesh_changes.h"
#include "render/surface_geometry.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"
#include "test_meshes.h"
#include "support/set_level.h"

namespace {

using render::MeshChanges;
using render::PositionSource;
using render::SlotRange;
using render::SurfaceGeometry;

void expect_equals_rebuild(const rgb::Mesh& mesh, const SurfaceGeometry& incremental) {
    SurfaceGeometry fresh(incremental.source());
    fresh.set_detail_distance(incremental.detail_distance());
    fresh.rebuild(mesh);
    ASSERT_EQ(incremental.vertices().size(), fresh.vertices().size());
    for (std::size_t i = 0; i < fresh.vertices().size(); ++i)
        ASSERT_EQ(incremental.vertices()[i], fresh.vertices()[i]) << "vertex " << i << " of face slot " << i / 3;
}

bool in_ranges(std::uint32_t slot, const std::vector<SlotRange>& ranges) {
    return std::any_of(ranges.begin(), ranges.end(),
                       [slot](const SlotRange& r) { return slot >= r.first && slot < r.first + r.count; });
}

class SurfaceGeometryTest : public ::testing::TestWithParam<PositionSource> {};

TEST_P(SurfaceGeometryTest, IncrementalUpdatesEqualARebuildThroughRefineAndCoarsen) {
    rgb::Mesh mesh = render_test::icosphere(1);
    MeshChanges changes(mesh);
    SurfaceGeometry geometry(GetParam());
    geometry.rebuild(mesh);

    const rgb::Sphere cap{{0.0, 0.0, 1.0}, 0.6};
    for (int target : {1, 3, 2, 0}) {
        rgbtest::set_level(mesh, target, cap);
        geometry.update(mesh, changes);
        changes.clear();
        SCOPED_TRACE(testing::Message() << "after set_level " << target);
        expect_equals_rebuild(mesh, geometry);
    }
}

TEST_P(SurfaceGeometryTest, ColourCountsFollowTheMesh) {
    rgb::Mesh mesh = render_test::icosphere(1);
    MeshChanges changes(mesh);
    SurfaceGeometry geometry(GetParam());
    geometry.rebuild(mesh);
    rgbtest::set_level(mesh, 2, rgb::Sphere{{1.0, 0.0, 0.0}, 0.5});
    geometry.update(mesh, changes);

    std::size_t counts[3] = {0, 0, 0};
    int max_level = 0;
    for (rgb::FaceId f : mesh.faces()) {
        ++counts[static_cast<int>(mesh.colour(f))];
        max_level = std::max(max_level, mesh.level(f));
    }
    EXPECT_EQ(geometry.triangles_of(rgb::Colour::Green), counts[0]);
    EXPECT_EQ(geometry.triangles_of(rgb::Colour::Red), counts[1]);
    EXPECT_EQ(geometry.triangles_of(rgb::Colour::Blue), counts[2]);
    EXPECT_GT(counts[1] + counts[2], 0u) << "a local refinement leaves red/blue transition triangles";
    EXPECT_EQ(geometry.max_face_level(), max_level);
}

// What the statistics panel shows: the counts kept as slots are written against a count of the
// mesh's faces, through random refinements and coarsenings (each update a part, as the editor's
// display catches up).
TEST_P(SurfaceGeometryTest, LevelAndColourCountsKeptIncrementallyEqualARecountAfterRandomEdits) {
    rgb::Mesh mesh = render_test::icosphere(1);
    MeshChanges changes(mesh);
    SurfaceGeometry geometry(GetParam());
    geometry.rebuild(mesh);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0), radius(0.2, 0.8);
    std::uniform_int_distribution<int> level(0, 4);
    int deepest = 0;
    for (int edit = 0; edit < 12; ++edit) {
        rgbtest::set_level(mesh, level(random), rgb::Sphere{{coordinate(random), coordinate(random), coordinate(random)}, radius(random)});
        const std::span<const rgb::FaceId> faces = changes.changed_faces();
        const std::size_t half = faces.size() / 2;
        geometry.update_part(mesh, faces.first(half), {});
        geometry.update_part(mesh, faces.subspan(half), changes.moved_vertices());
        changes.clear();

        std::array<std::size_t, 256> per_level{};
        std::array<std::size_t, 3> per_colour{};
        for (rgb::FaceId f : mesh.faces()) {
            ++per_level[static_cast<std::size_t>(mesh.level(f))];
            ++per_colour[static_cast<std::size_t>(mesh.colour(f))];
        }
        SCOPED_TRACE(testing::Message() << "after edit " << edit << ", " << mesh.num_faces() << " faces");
        for (int l = 0; l < 256; ++l) ASSERT_EQ(geometry.triangles_at(l), per_level[static_cast<std::size_t>(l)]) << "level " << l;
        EXPECT_EQ(geometry.triangles_of(rgb::Colour::Green), per_colour[0]);
        EXPECT_EQ(geometry.triangles_of(rgb::Colour::Red), per_colour[1]);
        EXPECT_EQ(geometry.triangles_of(rgb::Colour::Blue), per_colour[2]);
        deepest = std::max(deepest, geometry.max_face_level());
    }
    EXPECT_GE(deepest, 3) << "the edits reached deep levels";
}

INSTANTIATE_TEST_SUITE_P(Positions, SurfaceGeometryTest, ::testing::Values(PositionSource::Displayed, PositionSource::Limit));

TEST(SurfaceGeometry, OneSplitRewritesOnlyItsNeighbourhood) {
    rgb::Mesh mesh = render_test::icosphere(3);  // 1280 faces
    MeshChanges changes(mesh);
    SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    const std::vector<render::SurfaceVertex> before(geometry.vertices().begin(), geometry.vertices().end());

    const auto& corners = mesh.face_vertices(rgb::FaceId(0));
    ASSERT_TRUE(rgb::refine_edge(mesh, corners[0], corners[1]));
    const std::vector<SlotRange> ranges = geometry.update(mesh, changes);

    std::size_t rewritten = 0;
    for (const SlotRange& r : ranges) rewritten += r.count;
    for (std::uint32_t slot = 0; slot < geometry.face_slots(); ++slot) {
        const bool changed = slot >= before.size() / 3 ||
                             !std::equal(before.begin() + 3 * slot, before.begin() + 3 * slot + 3, geometry.vertices().begin() + 3 * slot);
        if (changed) {
            EXPECT_TRUE(in_ranges(slot, ranges)) << "face slot " << slot << " changed but is not uploaded";
        }
    }
    // A GG-split replaces 2 faces by 4 and moves 4 vertices: with their rings' normals that is a few
    // dozen faces, far from the 1280 of a full upload.
    EXPECT_GT(rewritten, 0u);
    EXPECT_LT(rewritten, 100u);
    expect_equals_rebuild(mesh, geometry);
}

// On a cage with detail each face's code carries the band of its distance to the dense surface, found
// independently here (brute force over the detail's points), as a share of the base mesh's
// bounding-box diagonal; it follows refining and coarsening (new faces and reused slots) as a rebuild
// gives it, and the bands stay 0 where the distance is not measured.
TEST(SurfaceGeometry, DetailDistanceBandsAreEachFacesDistanceToTheDenseSurface) {
    rgb::Mesh mesh = render_test::bumpy_cage(0, 4);
    const double diagonal = rgb::bounding_box_diagonal(mesh.base());
    MeshChanges changes(mesh);
    SurfaceGeometry geometry;
    geometry.set_detail_distance(true);
    geometry.rebuild(mesh);
    ASSERT_EQ(geometry.distance_scale(), diagonal);
    std::array<int, render::kDistanceBands> faces_per_band{};
    const auto expect_bands = [&] {
        for (rgb::FaceId f : mesh.faces()) {
            const int band = render::distance_band(render_test::brute_force_detail_distance(mesh, f) / diagonal);
            ++faces_per_band[static_cast<std::size_t>(band)];
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(geometry.vertices()[3 * f.idx + c].code >> render::kCodeDistanceShift, static_cast<std::uint32_t>(band))
                    << "face slot " << f.idx;
        }
    };
    expect_bands();
    for (int target : {2, 4, 3, 1}) {
        SCOPED_TRACE(testing::Message() << "after set_level " << target);
        rgbtest::set_level(mesh, target, rgb::Sphere{{0.3, 0.2, 0.9}, 0.8});
        geometry.update(mesh, changes);
        changes.clear();
        expect_bands();
        expect_equals_rebuild(mesh, geometry);
    }
    std::size_t bands_seen = 0;
    for (int count : faces_per_band) bands_seen += count > 0;
    EXPECT_GE(bands_seen, 5u) << "the test sees several bands, the finest faces' (on the detail) among them";
    EXPECT_GT(faces_per_band[0], 0);

    SurfaceGeometry unmeasured;
    unmeasured.rebuild(mesh);
    EXPECT_FALSE(unmeasured.distance_scale());
    for (const render::SurfaceVertex& v : unmeasured.vertices()) EXPECT_EQ(v.code >> render::kCodeDistanceShift, 0u);
    SurfaceGeometry without_detail;
    without_detail.set_detail_distance(true);
    without_detail.rebuild(render_test::icosphere(1));
    EXPECT_FALSE(without_detail.distance_scale()) << "nothing to measure against";
}

}  // namespace
