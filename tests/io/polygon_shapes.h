#pragma once
// Large simple polygons of known area for the triangulation test and benchmark, in the plane z = 0.
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace rgbio::test {

// `corners` points on the unit circle, counter-clockwise; area -> pi.
inline std::vector<glm::dvec3> circle_polygon(int corners) {
    std::vector<glm::dvec3> p;
    for (int i = 0; i < corners; ++i) {
        const double a = 2 * std::numbers::pi * i / corners;
        p.push_back({std::cos(a), std::sin(a), 0});
    }
    return p;
}

// A star of `spikes` tips at radius 1 and notches at radius 0.3, counter-clockwise; its area is
// 2 * spikes triangles (centre, tip, notch) of 1 * 0.3 * sin(pi / spikes) / 2 each.
inline std::vector<glm::dvec3> star_polygon(int spikes) {
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 2 * spikes; ++i) {
        const double a = std::numbers::pi * i / spikes, r = i % 2 ? 0.3 : 1.0;
        p.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    return p;
}
inline double star_area(int spikes) { return spikes * 0.3 * std::sin(std::numbers::pi / spikes); }

// A comb of `teeth` teeth 1 wide and 10 high, 2 apart, on a bar 1 high, clockwise: after its teeth,
// only a fan from the bar's two far corners triangulates the bar. Area 12 * teeth - 0.5.
inline std::vector<glm::dvec3> comb_polygon(int teeth) {
    std::vector<glm::dvec3> p;
    for (int k = 0; k < teeth; ++k)
        for (const auto& [dx, y] : {std::pair{0, 0}, std::pair{0, 10}, std::pair{1, 10}, std::pair{1, 0}})
            p.push_back({2.0 * k + dx, double(y), 0});
    p.push_back({2.0 * teeth, -1, 0});
    p.push_back({0, -1, 0});
    return p;
}
inline double comb_area(int teeth) { return 12.0 * teeth - 0.5; }

// A strip 0.4 wide winding 20 times around the origin: out along one rail, back along the other.
inline std::vector<glm::dvec3> spiral_polygon(int corners) {
    std::vector<glm::dvec3> p;
    const int half = corners / 2;
    for (int side = 0; side < 2; ++side)
        for (int k = 0; k < half; ++k) {
            const double t = 40.0 * (side ? half - 1 - k : k) / half, r = 1 + t - (side ? 0.4 : 0.0);
            p.push_back({r * std::cos(t * std::numbers::pi), r * std::sin(t * std::numbers::pi), 0});
        }
    return p;
}

}  // namespace rgbio::test
