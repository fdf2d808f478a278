#pragma once
// The shape of triangles, for finite-element users who ask a mesh for well-shaped cells (`rgbsub info`,
// the cell data of .vtu and .msh files): each triangle's smallest interior angle and its aspect ratio,
// and those summed up per level of the adaptive mesh.
//
// Aspect ratio (Verdict's triangle aspect ratio): the longest edge times the perimeter over 4√3 times
// the area, L·(a+b+c) / (4√3·A). It is 1 for an equilateral triangle, grows without bound as a
// triangle flattens, and is +infinity for a triangle of zero area.
#include <cstddef>
#include <map>
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {

class Mesh;

struct TriangleQuality {
    double min_angle = 0.0;  // degrees; 0 for a triangle with a zero-length edge
    double aspect_ratio = 0.0;
};

TriangleQuality triangle_quality(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

struct QualitySummary {
    std::size_t triangles = 0;
    double min_angle = 180.0;      // the smallest angle of any triangle, degrees
    double mean_min_angle = 0.0;   // the mean over the triangles of each one's smallest angle, degrees
    double max_aspect_ratio = 0.0; // the worst
};

// Per face level present, over the live faces at their displayed positions.
std::map<int, QualitySummary> quality_by_level(const Mesh& mesh);

}  // namespace rgb
