#pragma once
// A bounding-volume hierarchy over the base mesh's triangles (in base space, where they never move),
// so that a request finds the base faces its sphere meets in logarithmic time instead of scanning
// every face (spec §3.5).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {

class BaseMesh;

class BaseFaceIndex {
public:
    explicit BaseFaceIndex(const BaseMesh& base);

    // Base faces whose closed triangle meets the closed ball, in increasing id order.
    std::vector<std::uint32_t> faces_meeting_sphere(const glm::dvec3& centre, double radius) const;

    std::size_t memory_bytes() const;

private:
    struct Node {
        glm::dvec3 lo, hi;
        std::uint32_t first, count;  // leaf: faces_[first, first+count); inner: count == 0, children first, first+1
    };
    struct FaceBox {
        glm::dvec3 lo, hi, centroid;  // centroid times three
    };
    void build(const std::vector<FaceBox>& boxes, std::uint32_t node, std::uint32_t begin, std::uint32_t end);

    const BaseMesh& base_;
    std::vector<std::uint32_t> faces_;
    std::vector<Node> nodes_;
};

}  // namespace rgb
