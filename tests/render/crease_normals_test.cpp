// Shading breaks along infinitely sharp creases (issue 13): a corner's normal averages only the faces
// on its side of the creases through its vertex. On the machined part with its rim and corner edges
// tagged, every face lies in a flat region bounded by creases, so every corner's normal is its own
// face's normal; untagged, the rounded part has none like that at the rims. Incremental updates still
// equal a rebuild, and so do the sharp edges' lines followed slot by slot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/mesh_changes.h"
#include "render/sharp_edge_lines.h"
#include "render/surface_geometry.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/mesh/sharp_edges.h"
#include "support/obj_reader.h"
#include "support/set_level.h"

namespace {

rgb::Mesh machined_part(bool tagged) {
    const rgbtest::TestMesh part = rgbtest::read_obj(RGBSUB_ASSETS_DIR "/machined_part.obj");
    rgb::SharpFeatures features;
    if (tagged) features.edges = rgb::edges_sharper_than(rgb::BaseMesh(part.positions, part.triangles), 30.0);
    return rgb::Mesh(std::make_shared<const rgb::BaseMesh>(part.positions, part.triangles, features));
}

// The largest angle (degrees) between a corner's normal and its face's normal.
double worst_corner_deviation(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry) {
    double worst = 0.0;
    for (rgb::FaceId f : mesh.faces()) {
        const auto c = geometry.corners(f);
        const glm::dvec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3 corner(geometry.vertices()[3 * f.idx + static_cast<std::size_t>(i)].normal);
            worst = std::max(worst, glm::degrees(std::acos(std::clamp(glm::dot(n, glm::normalize(corner)), -1.0, 1.0))));
        }
    }
    return worst;
}

TEST(CreaseNormals, EveryCornerOfTheTaggedPartTakesItsFlatRegionsNormal) {
    rgb::Mesh tagged = machined_part(true), plain = machined_part(false);
    rgb::refine_uniform(tagged, 2);
    rgb::refine_uniform(plain, 2);
    render::SurfaceGeometry a, b;
    a.rebuild(tagged);
    b.rebuild(plain);
    EXPECT_LT(worst_corner_deviation(tagged, a), 0.01) << "float positions: a hundredth of a degree";
    EXPECT_GT(worst_corner_deviation(plain, b), 20.0);
}

TEST(CreaseNormals, IncrementalUpdatesOfATaggedMeshEqualARebuild) {
    rgb::Mesh mesh = machined_part(true);
    render::MeshChanges changes(mesh);
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    for (int level : {2, 3, 1, 0}) {
        rgbtest::set_level(mesh, level, rgb::Sphere{{4.0, 0.0, 2.0}, 1.5});
        geometry.update(mesh, changes);
        changes.clear();
        render::SurfaceGeometry fresh;
        fresh.rebuild(mesh);
        ASSERT_EQ(geometry.vertices().size(), fresh.vertices().size());
        for (std::size_t i = 0; i < fresh.vertices().size(); ++i)
            ASSERT_EQ(geometry.vertices()[i], fresh.vertices()[i]) << "slot " << i / 3 << " after level " << level;
    }
}

// What the editor draws of the creases after each change (render::SharpEdgeLines::update over the
// slots the change rewrote) is what a look at every slot finds: one line per edge rgb::sharp_mesh_edges
// lists, at the corners shown.
TEST(CreaseNormals, SharpEdgeLinesFollowedSlotBySlotEqualALookAtEverySlot) {
    rgb::Mesh mesh = machined_part(true);
    render::MeshChanges changes(mesh);
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    render::SharpEdgeLines followed;
    followed.rebuild(mesh);
    for (int level : {2, 3, 1, 0}) {
        rgbtest::set_level(mesh, level, rgb::Sphere{{4.0, 0.0, 2.0}, 1.5});
        followed.update(mesh, geometry.update(mesh, changes));
        changes.clear();
        render::SharpEdgeLines fresh;
        fresh.rebuild(mesh);
        const std::vector<glm::vec3> lines = fresh.lines(geometry);
        EXPECT_EQ(followed.lines(geometry), lines) << "after level " << level;
        EXPECT_EQ(lines.size(), 2 * rgb::sharp_mesh_edges(mesh).size()) << "after level " << level;
    }
}

}  // namespace
