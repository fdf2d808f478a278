// The triangle quality of rgb/values/triangle_quality.h against an independent computation: angles by
// the law of cosines, the area by Heron's formula, and exact values of known triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "rgb/mesh/mesh.h"
#include "rgb/lod/requests.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/triangle_quality.h"
#include "support/test_meshes.h"

namespace {

struct Reference {
    double min_angle, aspect_ratio;
};

Reference law_of_cosines(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
    const double a = glm::distance(q, r), b = glm::distance(r, p), c = glm::distance(p, q);
    const auto angle = [](double opposite, double x, double y) {
        return std::acos(std::clamp((x * x + y * y - opposite * opposite) / (2 * x * y), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    };
    const double s = (a + b + c) / 2, area = std::sqrt(s * (s - a) * (s - b) * (s - c));
    return {std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)}), std::max({a, b, c}) * (a + b + c) / (4 * std::sqrt(3.0) * area)};
}

TEST(TriangleQuality, KnownTriangles) {
    const rgb::TriangleQuality equilateral = rgb::triangle_quality({0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0});
    EXPECT_NEAR(equilateral.min_angle, 60.0, 1e-12);
    EXPECT_NEAR(equilateral.aspect_ratio, 1.0, 1e-12);
    // Right isosceles: legs 1, hypotenuse sqrt 2, area 1/2: sqrt2 (2 + sqrt2) / (4 sqrt3 / 2) = (sqrt2 + 1) / sqrt3.
    const rgb::TriangleQuality right = rgb::triangle_quality({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_NEAR(right.min_angle, 45.0, 1e-12);
    EXPECT_NEAR(right.aspect_ratio, (std::sqrt(2.0) + 1) / std::sqrt(3.0), 1e-12);
    const rgb::TriangleQuality flat = rgb::triangle_quality({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
    EXPECT_EQ(flat.min_angle, 0.0);
    EXPECT_TRUE(std::isinf(flat.aspect_ratio));
}

TEST(TriangleQuality, AgreesWithLawOfCosinesAndHeron) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 p(coordinate(random), coordinate(random), coordinate(random));
        const glm::dvec3 q(coordinate(random), coordinate(random), coordinate(random));
        const glm::dvec3 r(coordinate(random), coordinate(random), coordinate(random));
        const rgb::TriangleQuality got = rgb::triangle_quality(p, q, r);
        const Reference wanted = law_of_cosines(p, q, r);
        if (wanted.aspect_ratio > 1e4) continue;  // Heron loses its digits on needles
        EXPECT_NEAR(got.min_angle, wanted.min_angle, 1e-7) << i;
        EXPECT_NEAR(got.aspect_ratio / wanted.aspect_ratio, 1.0, 1e-9) << i;
    }
}

TEST(TriangleQuality, SummaryPerLevelCoversEveryFaceOnce) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::octahedron());
    rgb::LevelRequest request;
    request.level = 2;
    request.sphere = rgb::Sphere{{1, 0, 0}, 0.8};
    rgb::apply_request(mesh, request);
    const std::map<int, rgb::QualitySummary> summary = rgb::quality_by_level(mesh);
    std::map<int, std::size_t> faces;
    std::map<int, double> smallest, sum, worst;
    for (rgb::FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        const Reference q = law_of_cosines(rgb::displayed_position(mesh, v[0]), rgb::displayed_position(mesh, v[1]),
                                           rgb::displayed_position(mesh, v[2]));
        const int level = mesh.level(f);
        smallest[level] = faces[level] ? std::min(smallest[level], q.min_angle) : q.min_angle;
        worst[level] = std::max(worst[level], q.aspect_ratio);
        sum[level] += q.min_angle;
        ++faces[level];
    }
    ASSERT_EQ(summary.size(), faces.size());
    ASSERT_GE(summary.size(), 2u);
    for (const auto& [level, s] : summary) {
        EXPECT_EQ(s.triangles, faces[level]);
        EXPECT_NEAR(s.min_angle, smallest[level], 1e-9);
        EXPECT_NEAR(s.mean_min_angle, sum[level] / double(faces[level]), 1e-9);
        EXPECT_NEAR(s.max_aspect_ratio, worst[level], 1e-9);
    }
}

}  // namespace
