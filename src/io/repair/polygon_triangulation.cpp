#include "io/repair/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <set>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "io/repair/corner_grid.h"

namespace rgbio {

namespace {

// Newell's method: robust normal of a possibly non-planar polygon, length = twice the area.
glm::dvec3 newell_normal(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> polygon) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = positions[polygon[i]];
        const glm::dvec3& b = positions[polygon[(i + 1) % polygon.size()]];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

// The polygon in its best-fit plane, winding counter-clockwise.
std::vector<glm::dvec2> project(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> polygon) {
    glm::dvec3 normal = newell_normal(positions, polygon);
    const double length = glm::length(normal);
    normal = length > 0 ? normal / length : glm::dvec3(0, 0, 1);
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, normal));
    const glm::dvec3 v = glm::cross(normal, u);
    std::vector<glm::dvec2> projected(polygon.size());
    for (std::size_t i = 0; i < polygon.size(); ++i)
        projected[i] = glm::dvec2(glm::dot(positions[polygon[i]], u), glm::dot(positions[polygon[i]], v));
    return projected;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool strictly_inside(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return cross2(a, b, p) > 0 && cross2(b, c, p) > 0 && cross2(c, a, p) > 0;
}

class EarClipper {
public:
    explicit EarClipper(std::vector<glm::dvec2> points)
        : points_(std::move(points)), n_(static_cast<std::uint32_t>(points_.size())), prev_(n_), next_(n_), alive_(n_, 1),
          status_(n_, Status::Unknown), blocker_(n_, kNone), blocked_(n_), version_(n_, 0), grid_(points_, initially_reflex()) {
        for (std::uint32_t i = 0; i < n_; ++i) {
            candidates_.insert(candidates_.end(), i);
            push_convexity(i);
        }
    }

    std::vector<std::array<std::uint32_t, 3>> run(std::uint64_t budget) {
        std::vector<std::array<std::uint32_t, 3>> triangles;
        triangles.reserve(n_ - 2);
        std::uint32_t remaining = n_, scan = 0;
        while (remaining > 3) {
            if (work_ > budget) return {};
            auto it = candidates_.lower_bound(scan);
            if (it == candidates_.end()) it = candidates_.begin();
            std::uint32_t clip;
            if (it == candidates_.end()) {
                clip = most_convex();  // no true ear: degenerate or self-intersecting input
            } else {
                clip = *it;
                if (status_[clip] == Status::Unknown) status_[clip] = ear_test(clip);
                if (status_[clip] == Status::NotEar) {
                    candidates_.erase(it);
                    scan = clip + 1;
                    continue;
                }
            }
            triangles.push_back({prev_[clip], clip, next_[clip]});
            remove(clip);
            --remaining;
            scan = next_[next_[clip]];  // resume past the ear, which keeps ears small
        }
        std::uint32_t first = 0;
        while (!alive_[first]) ++first;
        triangles.push_back({first, next_[first], next_[next_[first]]});
        return triangles;
    }

private:
    enum class Status : std::uint8_t { Unknown, Ear, NotEar };
    static constexpr std::uint32_t kNone = UINT32_MAX;

    double convexity(std::uint32_t i) const { return cross2(points_[prev_[i]], points_[i], points_[next_[i]]); }

    // Also links the corners into the polygon's ring. Clipping only shrinks the angles of the
    // remaining corners, so no corner becomes reflex later.
    std::vector<std::uint8_t> initially_reflex() {
        std::vector<std::uint8_t> reflex(n_);
        for (std::uint32_t i = 0; i < n_; ++i) {
            prev_[i] = (i + n_ - 1) % n_;
            next_[i] = (i + 1) % n_;
        }
        for (std::uint32_t i = 0; i < n_; ++i) reflex[i] = convexity(i) < 0;
        return reflex;
    }

    // Convex, and no other remaining corner strictly inside; a blocking corner is remembered. Only
    // reflex corners are looked at: in a simple polygon, a triangle of three consecutive corners
    // that holds some corner holds a reflex one.
    Status ear_test(std::uint32_t b) {
        const std::uint32_t a = prev_[b], c = next_[b];
        const glm::dvec2 &pa = points_[a], &pb = points_[b], &pc = points_[c];
        if (cross2(pa, pb, pc) <= 0) return Status::NotEar;
        std::uint32_t blocker = kNone;
        work_ += grid_.visit(pa, pb, pc, [&](std::uint32_t p) {
            if (p == a || p == c || !strictly_inside(points_[p], pa, pb, pc)) return false;
            blocker = p;
            return true;
        });
        if (blocker == kNone) return Status::Ear;
        blocker_[b] = blocker;
        blocked_[blocker].push_back(b);
        return Status::NotEar;
    }

    // Clipping changes the ears of the two neighbours and of the corners `i` was blocking.
    void remove(std::uint32_t i) {
        const std::uint32_t a = prev_[i], c = next_[i];
        next_[a] = c;
        prev_[c] = a;
        alive_[i] = 0;
        candidates_.erase(i);
        grid_.remove(i);
        for (std::uint32_t neighbour : {a, c}) {
            invalidate(neighbour);
            push_convexity(neighbour);
            if (convexity(neighbour) >= 0) grid_.remove(neighbour);
        }
        for (std::uint32_t blocked : blocked_[i])
            if (alive_[blocked] && blocker_[blocked] == i) invalidate(blocked);
        std::vector<std::uint32_t>().swap(blocked_[i]);
    }

    void invalidate(std::uint32_t i) {
        status_[i] = Status::Unknown;
        blocker_[i] = kNone;
        candidates_.insert(i);
    }

    // The most convex corner (the first one on ties), from a heap with stale entries skipped.
    struct Convexity {
        double value;
        std::uint32_t corner, version;
        bool operator<(const Convexity& o) const { return value != o.value ? value < o.value : corner > o.corner; }
    };
    void push_convexity(std::uint32_t i) { convexity_.push({convexity(i), i, ++version_[i]}); }
    std::uint32_t most_convex() {
        while (!alive_[convexity_.top().corner] || convexity_.top().version != version_[convexity_.top().corner]) convexity_.pop();
        return convexity_.top().corner;
    }

    std::vector<glm::dvec2> points_;
    std::uint32_t n_;
    std::vector<std::uint32_t> prev_, next_;
    std::vector<std::uint8_t> alive_;
    std::vector<Status> status_;
    std::vector<std::uint32_t> blocker_;
    std::vector<std::vector<std::uint32_t>> blocked_;
    std::vector<std::uint32_t> version_;
    CornerGrid grid_;  // the corners that are still reflex
    std::set<std::uint32_t> candidates_;  // corners not known to be non-ears, in polygon order
    std::priority_queue<Convexity> convexity_;
    std::uint64_t work_ = 0;
};

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate_polygon_corners(std::span<const glm::dvec3> positions,
                                                                      std::span<const std::uint32_t> polygon,
                                                                      std::optional<std::uint64_t> work_budget) {
    if (polygon.size() == 3) return {{0, 1, 2}};
    return EarClipper(project(positions, polygon)).run(work_budget.value_or(polygon_work_budget(polygon.size())));
}

std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const glm::dvec3> positions,
                                                              std::span<const std::uint32_t> polygon) {
    std::vector<std::array<std::uint32_t, 3>> triangles = triangulate_polygon_corners(positions, polygon);
    for (auto& t : triangles)
        for (std::uint32_t& corner : t) corner = polygon[corner];
    return triangles;
}

}  // namespace rgbio
