#include "rgb/lod/requests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "rgb/lod/refine.h"
#include "rgb/lod/request_steps.h"
#include "rgb/mesh/base_face_index.h"
#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/mesh_room_prefault.h"
#include "rgb/mesh/operators.h"
#include "rgb/support/triangle_geometry.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

namespace {

// Visit marks over face or vertex slots that cost O(1) to reset. Each function below that marks has
// instances of its own, so that none resets the marks of another while they are in use.
class Marks {
public:
    void start(std::size_t capacity) {
        if (stamp_.size() < capacity) stamp_.resize(capacity, 0);
        if (++current_ == 0) {
            std::fill(stamp_.begin(), stamp_.end(), 0);
            current_ = 1;
        }
    }
    bool marked(std::uint32_t i) const { return i < stamp_.size() && stamp_[i] == current_; }
    // Returns false if i was marked already.
    bool mark(std::uint32_t i) {
        if (i >= stamp_.size()) stamp_.resize(std::max<std::size_t>(i + 1, 2 * stamp_.size()), 0);
        if (stamp_[i] == current_) return false;
        stamp_[i] = current_;
        return true;
    }
    void unmark(std::uint32_t i) {
        if (i < stamp_.size()) stamp_[i] = 0;
    }

private:
    std::vector<std::uint32_t> stamp_;
    std::uint32_t current_ = 0;
};

std::array<glm::dvec3, 3> base_space(const BaseMesh& base, const std::array<SurfacePoint, 3>& t) {
    return {base_space_position(base, t[0]), base_space_position(base, t[1]), base_space_position(base, t[2])};
}

std::array<glm::dvec3, 3> base_triangle(const BaseMesh& base, std::uint32_t f) {
    const Triangle& t = base.face(f);
    return {base.position(t[0]), base.position(t[1]), base.position(t[2])};
}

// Which triangles of the hierarchy meet a region. Base faces the ball contains meet it in every
// sub-triangle without a test; base faces it misses never do; only the others test exactly. The
// answer for a triangle depends on nothing but the triangle and the region, whichever face or
// vertex asks.
class RegionTest {
public:
    enum class Coverage { None, Partial, Full };

    // `allowed` (sorted base faces, empty for all) must outlive the test.
    RegionTest(const Mesh& mesh, const std::optional<Sphere>& sphere, const std::vector<std::uint32_t>& allowed_faces, double dilation)
        : base_(mesh.base()), allowed_(allowed_faces) {
        if (!sphere) {
            whole_ = true;
            return;
        }
        sphere_ = *sphere;
        sphere_.radius += dilation;
        for (std::uint32_t f : base_.face_index().faces_meeting_sphere(sphere_.centre, sphere_.radius)) {
            if (!allowed(f)) continue;
            meeting_.push_back(f);
            contained_.push_back(sphere_contains_triangle(base_triangle(base_, f), sphere_.centre, sphere_.radius));
        }
    }

    const std::vector<std::uint32_t>& base_faces_meeting() const { return meeting_; }
    bool whole() const { return whole_; }

    Coverage coverage(std::uint32_t f) const {
        if (whole_) return allowed(f) ? Coverage::Full : Coverage::None;
        // Work runs face by face through a region, so the same base face is asked about in a row.
        if (f != last_face_) {
            last_face_ = f;
            const auto it = std::lower_bound(meeting_.begin(), meeting_.end(), f);
            const std::size_t i = static_cast<std::size_t>(it - meeting_.begin());
            last_coverage_ = it == meeting_.end() || *it != f ? Coverage::None : contained_[i] ? Coverage::Full : Coverage::Partial;
        }
        return last_coverage_;
    }

    // Whether the triangle (given by `triangle()`, computed only if needed) of base face f meets the region.
    template <class Triangle>
    bool meets(std::uint32_t f, Triangle&& triangle) const {
        switch (coverage(f)) {
            case Coverage::None: return false;
            case Coverage::Full: return true;
            case Coverage::Partial: break;
        }
        return triangle_meets_sphere(base_space(base_, triangle()), sphere_.centre, sphere_.radius);
    }

private:
    bool allowed(std::uint32_t f) const { return allowed_.empty() || std::binary_search(allowed_.begin(), allowed_.end(), f); }

    const BaseMesh& base_;
    const std::vector<std::uint32_t>& allowed_;
    bool whole_ = false;
    Sphere sphere_;
    std::vector<std::uint32_t> meeting_;  // sorted
    std::vector<bool> contained_;
    mutable std::uint32_t last_face_ = BaseMesh::kNone;
    mutable Coverage last_coverage_ = Coverage::None;
};

// Barycentric coordinates of the point of triangle (a, b, c) nearest to p (Ericson §5.1.5).
std::array<double, 3> nearest_barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {1, 0, 0};
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return {0, 1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return {0, 0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const double denom = 1.0 / (va + vb + vc);
    return {1 - (vb + vc) * denom, vb * denom, vc * denom};
}

// Finer than any vertex, so that every vertex's address is an integer point at this level.
constexpr int kLocateLevel = 24;

// For each base face, the face of the mesh holding the base face's point nearest the ball's centre (or
// its centroid): its parent triangle meets the region, and the region's faces are connected to it.
std::vector<FaceId> seed_faces(const Mesh& mesh, std::span<const std::uint32_t> base_faces, const std::optional<Sphere>& sphere) {
    std::vector<FaceId> seeds;
    for (std::uint32_t b : base_faces) {
        const auto t = base_triangle(mesh.base(), b);
        const auto w = sphere ? nearest_barycentric(sphere->centre, t[0], t[1], t[2]) : std::array<double, 3>{1 / 3.0, 1 / 3.0, 1 / 3.0};
        const double scale = std::ldexp(1.0, kLocateLevel);
        std::array<std::uint32_t, 3> target;
        target[1] = static_cast<std::uint32_t>(std::clamp(std::lround(w[1] * scale), 0l, static_cast<long>(scale)));
        target[2] = static_cast<std::uint32_t>(std::clamp(std::lround(w[2] * scale), 0l, static_cast<long>(scale) - target[1]));
        target[0] = static_cast<std::uint32_t>(scale) - target[1] - target[2];
        const FaceId f = face_containing(mesh, b, target, kLocateLevel);
        // The located face and its neighbours around its corners cover the target's surroundings,
        // whatever rounding did to the nearest point.
        seeds.push_back(f);
        for (VertexId v : mesh.face_vertices(f)) {
            const HalfedgeId start = mesh.vertex_halfedge(v);
            HalfedgeId h = start;
            do {
                seeds.push_back(Mesh::face(h));
                h = mesh.ccw_rotated(h);
            } while (h.valid() && h != start);
        }
    }
    return seeds;
}

// The live faces whose parent triangles meet the region: breadth over face adjacency from the seeds.
std::vector<FaceId> region_faces(const Mesh& mesh, const RegionTest& test, std::vector<FaceId> stack) {
    thread_local Marks face_marks;
    std::vector<FaceId> region;
    face_marks.start(mesh.face_capacity());
    while (!stack.empty()) {
        const FaceId f = stack.back();
        stack.pop_back();
        if (!mesh.is_live(f) || !face_marks.mark(f.idx)) continue;
        const std::uint32_t b = base_face_of(mesh, f);
        if (!test.meets(b, [&] { return parent_triangle(mesh, f, b); })) continue;
        region.push_back(f);
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId o = mesh.opposite(Mesh::halfedge(f, i));
            if (o.valid() && !face_marks.marked(Mesh::face(o).idx)) stack.push_back(Mesh::face(o));
        }
    }
    return region;
}

std::vector<FaceId> all_faces(const Mesh& mesh) {
    std::vector<FaceId> faces;
    faces.reserve(mesh.num_faces());
    for (FaceId f : mesh.faces()) faces.push_back(f);
    return faces;
}

std::vector<FaceId> starting_faces(const Mesh& mesh, const RegionTest& test, const LevelRequest& request) {
    if (request.sphere) return seed_faces(mesh, test.base_faces_meeting(), request.sphere);
    if (!request.base_faces.empty()) return seed_faces(mesh, request.base_faces, std::nullopt);
    return all_faces(mesh);
}

// The balls of a request with their levels, each with its own test, and the ball holding them all.
class Bands {
public:
    Bands(const Mesh& mesh, const LevelRequest& request, double dilation)
        : outer_(mesh, outermost(request), request.base_faces, dilation) {
        levels_.push_back(request.level);
        tests_.reserve(1 + request.taper.size());  // no moves: each test refers to the request's faces
        tests_.emplace_back(mesh, request.sphere, request.base_faces, 0.0);
        for (const LevelBand& band : request.taper) {
            levels_.push_back(band.level);
            tests_.emplace_back(mesh, Sphere{request.sphere->centre, band.radius}, request.base_faces, 0.0);
        }
    }
    // The region all bands lie in (dilated as asked).
    const RegionTest& outer() const { return outer_; }
    int coarsest() const { return *std::min_element(levels_.begin(), levels_.end()); }
    // The finest (refine) or coarsest (coarsen) level the bands that meet the triangle ask for, kNone
    // if none does (a plain int: this runs for every face a request visits); the triangle is computed
    // only if a band needs an exact test.
    static constexpr int kNone = -1;
    template <class Triangle>
    int level(std::uint32_t base_face, Triangle&& triangle, bool finest) const {
        std::optional<std::array<SurfacePoint, 3>> computed;
        auto exact = [&]() -> const std::array<SurfacePoint, 3>& {
            if (!computed) computed = triangle();
            return *computed;
        };
        // One ball (no taper), the common case: its level or none, without the search for the finest.
        if (tests_.size() == 1) return tests_[0].meets(base_face, exact) ? levels_[0] : kNone;
        int best = kNone;
        for (std::size_t i = 0; i < tests_.size(); ++i)
            if ((best == kNone || (finest ? levels_[i] > best : levels_[i] < best)) && tests_[i].meets(base_face, exact))
                best = levels_[i];
        return best;
    }

private:
    static std::optional<Sphere> outermost(const LevelRequest& request) {
        std::optional<Sphere> outer = request.sphere;
        for (const LevelBand& band : request.taper) outer->radius = std::max(outer->radius, band.radius);
        return outer;
    }
    RegionTest outer_;
    std::vector<int> levels_;
    std::vector<RegionTest> tests_;
};

// Room for what the request may add at once (estimated_triangles, an upper estimate), so that a large
// request does not regrow the arrays on the way (Mesh::reserve grows geometrically, so small requests
// after one another keep the amortised cost of doubling). Returns the faces it may add.
std::size_t reserve_for(Mesh& mesh, const LevelRequest& request) {
    const double estimate = estimated_triangles(mesh, request);
    if (!(estimate > static_cast<double>(mesh.num_faces()))) return 0;
    const std::size_t added = static_cast<std::size_t>(estimate) - mesh.num_faces();
    if (estimate > static_cast<double>(mesh.face_capacity())) mesh.reserve(mesh.num_faces() + added, mesh.num_vertices() + added / 2);
    return added;
}

// Level by level, like uniform refinement: a request for level N is the requests for levels 1..N in
// turn (each holds the last's vertices), and this way every split finds the limits of its coarser
// stencil points already known, computed cheaply while their rings were their neighbours. The region
// is searched once; after that, each pass works off the faces still short of their level and the
// faces the splits create.
// `known` holds the region's faces (or more) if a search just found them.
void refine_region(Mesh& mesh, const LevelRequest& request, OperatorLog& log, std::optional<std::vector<FaceId>> known) {
    thread_local Marks face_marks, vertex_marks;
    const Bands bands(mesh, request, 0.0);
    int finest = request.level;
    for (const LevelBand& band : request.taper) finest = std::max(finest, band.level);
    std::vector<FaceId> pending =
        known ? std::move(*known) : region_faces(mesh, bands.outer(), starting_faces(mesh, bands.outer(), request));
    // A large request has its room faulted in on another core ahead of the splits. Not a small one (a
    // brush dab, an editor frame's piece of a request): its splits take a few milliseconds, which a
    // thread's start and a join within a step of faulting would eat into.
    const std::size_t added = reserve_for(mesh, request);
    constexpr std::size_t kFacesWorthFaultingAhead = 1 << 17;
    std::optional<MeshRoomPrefault> room_ahead;
    if (added >= kFacesWorthFaultingAhead) room_ahead.emplace(mesh, added, added / 2);
    std::vector<FaceId> stack, next;
    for (int pass = 1; pass <= finest && !pending.empty(); ++pass) {
        // In slot order (the stack pops from the back), as uniform refinement sweeps: a split's new
        // faces take the old faces' slots, so neighbours in slot order are neighbours on the surface,
        // and the pass (its limits first) walks memory forward rather than in the order the last pass
        // deferred faces (a tenth of the general path's time on a 6k torus to level 4, net of the sort).
        std::sort(pending.begin(), pending.end(), [](FaceId x, FaceId y) { return x.idx > y.idx; });
        if (pass < finest) {
            vertex_marks.start(mesh.vertex_capacity());
            for (FaceId f : pending)
                for (VertexId v : mesh.face_vertices(f))
                    if (mesh.level(v) == pass - 1 && vertex_marks.mark(v.idx)) limit_position_where_uniform(mesh, v);
        }
        face_marks.start(mesh.face_capacity());
        stack.swap(pending);
        next.clear();
        while (!stack.empty()) {
            const FaceId f = stack.back();
            stack.pop_back();
            if (!mesh.is_live(f) || !face_marks.mark(f.idx)) continue;
            // A face this pass cannot refine is judged in the pass that can (if any is left), so that
            // each face's region test runs once.
            const int level = mesh.level(f);
            if (level >= pass) {
                if (level < finest) next.push_back(f);
                continue;
            }
            const std::uint32_t b = base_face_of(mesh, f);
            const int target = bands.level(b, [&] { return parent_triangle(mesh, f, b); }, true);
            // A face of level L is a triangle of ΣL or a red or blue piece of one, and a triangle of ΣL
            // is in an RGB mesh only as one of the four its parent was split into (and so on up): every
            // ancestor of f in Σj, j < L, is split into four, so a target <= L finds all the midpoints
            // it asks for here present.
            if (target <= level) continue;  // kNone included
            log.added.clear();
            refine_edge(mesh, edge_refining_face(mesh, f));
            // New faces may reuse slots visited before: they are new faces, so they get visited.
            for (auto it = log.added.rbegin(); it != log.added.rend(); ++it) {
                face_marks.unmark(it->idx);
                stack.push_back(*it);
            }
        }
        pending.swap(next);
    }
}

// Whether v lies on an edge of a triangle of level >= the level some band meeting that triangle asks
// for: its parent triangles are the triangles of Σ(level(v)-1) with v on an edge. Those two are all
// that need testing: every triangle of a finer Σj with v on its boundary lies inside one of them
// (around v the finer levels only subdivide its parent triangles), so if such a triangle meets a ball,
// so does the parent holding it; and a parent is itself a triangle of Σj, j = level(v) - 1, with
// j >= N exactly when level(v) > N.
bool above_its_level(const Mesh& mesh, const Bands& bands, VertexId v) {
    const PointStencil s = parent_stencil(mesh.base(), mesh.address(v));
    for (const SurfacePoint& o : s.opposite) {
        const int level = bands.level(o.face, [&] { return std::array<SurfacePoint, 3>{s.ends[0], s.ends[1], o}; }, false);
        if (level != Bands::kNone && mesh.level(v) > level) return true;
    }
    return false;
}

// Returns the faces it searched (a superset of the region) if it removed nothing.
std::optional<std::vector<FaceId>> coarsen_region(Mesh& mesh, const LevelRequest& request) {
    // Every vertex to remove lies on a triangle of level >= N that meets a ball, so within one such
    // triangle's size of it.
    const Bands probe(mesh, request, 0.0);
    const Bands bands(mesh, request, std::ldexp(mesh.base().longest_edge(), -probe.coarsest()));
    thread_local Marks vertex_marks;
    std::vector<VertexId> doomed;
    vertex_marks.start(mesh.vertex_capacity());
    std::vector<FaceId> searched = region_faces(mesh, bands.outer(), starting_faces(mesh, bands.outer(), request));
    for (FaceId f : searched)
        for (VertexId v : mesh.face_vertices(f))
            if (mesh.level(v) > bands.coarsest() && vertex_marks.mark(v.idx) && above_its_level(mesh, probe, v))
                doomed.push_back(v);
    if (doomed.empty()) return searched;
    remove_finest_first(mesh, std::move(doomed));
    return std::nullopt;
}

// Everything above level N goes, finest first: each is then removable. Returns the removals.
std::size_t coarsen_everywhere(Mesh& mesh, int level) {
    const std::vector<std::vector<VertexId>> by_level = vertices_above_by_level(mesh, level);
    std::size_t removed = 0;
    for (auto it = by_level.rbegin(); it != by_level.rend(); ++it)
        for (VertexId v : *it) {
            remove_vertex(mesh, v);
            ++removed;
        }
    return removed;
}

void check_level(int level) {
    if (level < 0 || level > kMaxLevel)
        throw std::invalid_argument("level " + std::to_string(level) + " is outside 0.." + std::to_string(kMaxLevel));
}

void check(const LevelRequest& request) {
    check_level(request.level);
    for (const LevelBand& band : request.taper) {
        check_level(band.level);
        if (!request.sphere || request.kind == RequestKind::Set || !(band.radius > 0.0 && std::isfinite(band.radius)))
            throw std::invalid_argument("a taper needs a refine or coarsen request with a sphere, and positive radii");
    }
    check_sphere(request.sphere);
}

}  // namespace

RequestStats apply_request(Mesh& mesh, const LevelRequest& request) {
    check(request);
    if (!request.sphere && request.base_faces.empty()) {
        // The whole surface needs no bookkeeping of new faces: the counts tell what happened.
        RequestStats stats;
        if (request.kind != RequestKind::Refine) stats.removals = coarsen_everywhere(mesh, request.level);
        const std::size_t before = mesh.num_vertices();
        if (request.kind != RequestKind::Coarsen) refine_uniform(mesh, request.level);
        stats.splits = mesh.num_vertices() - before;
        return stats;
    }
    OperatorLog log(mesh);
    std::optional<std::vector<FaceId>> searched;
    if (request.kind != RequestKind::Refine) searched = coarsen_region(mesh, request);
    if (request.kind != RequestKind::Coarsen) refine_region(mesh, request, log, std::move(searched));
    RequestStats stats;
    stats.splits = log.splits;
    stats.removals = log.removals;
    return stats;
}

std::vector<FaceId> faces_meeting(const Mesh& mesh, const Sphere& sphere) {
    static const std::vector<std::uint32_t> every_base_face;  // the test keeps a reference
    const RegionTest test(mesh, sphere, every_base_face, 0.0);
    return region_faces(mesh, test, seed_faces(mesh, test.base_faces_meeting(), sphere));
}

double estimated_triangles(const Mesh& mesh, const LevelRequest& request) {
    check(request);
    if (request.kind == RequestKind::Coarsen) return static_cast<double>(mesh.num_faces());
    const BaseMesh& base = mesh.base();
    const double per_base_face = std::ldexp(1.0, 2 * request.level);
    const RegionTest test(mesh, request.sphere, request.base_faces, 0.0);
    double added = 0.0;
    auto add = [&](std::uint32_t f) {
        if (!request.sphere) {
            added += per_base_face;
            return;
        }
        // The ball covers at most its disc of the base face, plus the triangles its rim crosses.
        const auto t = base_triangle(base, f);
        const double area = 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
        const double r = request.sphere->radius;
        const double edge = std::ldexp(std::max({glm::distance(t[0], t[1]), glm::distance(t[1], t[2]), glm::distance(t[2], t[0])}),
                                       -request.level);
        const double covered = area > 0.0 ? (3.15 * r * r + 4.0 * 3.15 * r * edge + 2.0 * edge * edge) / area : 1.0;
        added += per_base_face * std::min(1.0, covered);
    };
    if (test.whole()) {
        for (std::uint32_t f = 0; f < base.num_faces(); ++f)
            if (test.coverage(f) != RegionTest::Coverage::None) add(f);
    } else {
        for (std::uint32_t f : test.base_faces_meeting()) add(f);
    }
    return static_cast<double>(mesh.num_faces()) + added;
}

}  // namespace rgb
