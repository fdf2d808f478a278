#include "detail/cage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/CollapseInfoT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Utils/HeapT.hh>

namespace rgbdetail {
namespace {

// ---------------------------------------------------------------------------------------------
// OpenMesh
// ---------------------------------------------------------------------------------------------

struct CageTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using CageMesh = OpenMesh::TriMesh_ArrayKernelT<CageTraits>;

// The boundary loop of each boundary vertex (-1 inside), and the fewest edges each loop keeps.
// Collapses keep boundary vertices on their loops (BaseDecimaterT never moves one inside), so the
// labels set once stay right.
struct LoopLimits {
    OpenMesh::VPropHandleT<int> loop;
    std::vector<std::size_t> min_edges;
};

// Refuses, besides OpenMesh's own tests, the collapse of an ear (a face whose two other edges are
// boundary: collapsing would leave a dangling edge) and of a boundary edge of a loop at its fewest
// edges (3, or more where the smallest cage needs every vertex on the boundary, as a torus with one
// hole: 6). In the tests OpenMesh's tests alone never broke the topology; the loop limits are what
// lets a torus with holes reach its smallest cage.
template <class MeshT>
class ModTopologyGuardT : public OpenMesh::Decimater::ModBaseT<MeshT> {
public:
    DECIMATING_MODULE(ModTopologyGuardT, MeshT, TopologyGuard);

    explicit ModTopologyGuardT(MeshT& mesh) : Base(mesh, true) {}

    void set_limits(const LoopLimits* limits) { limits_ = limits; }

    float collapse_priority(const CollapseInfo& ci) override {
        const MeshT& m = Base::mesh();
        // CollapseInfo's vlv1, v0vl (vrv0, v1vr) are the halfedges outside the left (right) face.
        auto ear = [&](typename MeshT::HalfedgeHandle a, typename MeshT::HalfedgeHandle b) {
            return a.is_valid() && b.is_valid() && m.is_boundary(a) && m.is_boundary(b);
        };
        if (ci.vl.is_valid() && ear(ci.vlv1, ci.v0vl)) return Base::ILLEGAL_COLLAPSE;
        if (ci.vr.is_valid() && ear(ci.vrv0, ci.v1vr)) return Base::ILLEGAL_COLLAPSE;
        // The collapse deletes the edges v0-vl and v0-vr (each merges into v1's edge to vl, vr): a
        // feature edge among them would leave its chain broken. (BaseDecimaterT itself lets a feature
        // vertex go only along a feature edge.)
        auto feature = [&](typename MeshT::HalfedgeHandle h) { return h.is_valid() && m.status(m.edge_handle(h)).feature(); };
        if ((ci.vl.is_valid() && feature(ci.v0vl)) || (ci.vr.is_valid() && feature(ci.vrv0))) return Base::ILLEGAL_COLLAPSE;
        for (auto h : {ci.v0v1, ci.v1v0}) {
            if (!m.is_boundary(h)) continue;
            std::size_t keep = 3;
            if (limits_ != nullptr) {
                const int loop = m.property(limits_->loop, m.to_vertex_handle(h));
                if (loop >= 0) keep = std::max(keep, limits_->min_edges[static_cast<std::size_t>(loop)]);
            }
            // Walk at most keep edges: back at h means the loop has no more than keep.
            auto g = h;
            std::size_t length = 0;
            do {
                g = m.next_halfedge_handle(g);
                ++length;
            } while (g != h && length <= keep);
            if (g == h && length <= keep) return Base::ILLEGAL_COLLAPSE;
        }
        return Base::LEGAL_COLLAPSE;
    }

private:
    const LoopLimits* limits_ = nullptr;
};

// The share of a component's decimation done, told to CageOptions::progress: the faces removed of
// those to remove, from its face count at the start down to its share.
struct DecimationProgress {
    const ProgressFunction* progress = nullptr;
    std::size_t start_faces = 0, goal_faces = 0;

    void tell(std::size_t faces) const {
        if (start_faces <= goal_faces) return;
        const double removed = static_cast<double>(start_faces - std::min(faces, start_faces));
        report_share(*progress, std::min(1.0, removed / static_cast<double>(start_faces - goal_faces)));
    }
};

// The collapses of a decimation pass, with OpenMesh's modules (ModQuadricT's error as the priority,
// ModNormalFlippingT's limit, our guard) and OpenMesh's collapse. The bulk is collapsed by multiple
// choices, the rest exactly as OpenMesh's DecimaterT collapses, below.
class Decimation {
public:
    using CollapseInfo = OpenMesh::Decimater::CollapseInfoT<CageMesh>;
    using VertexHandle = CageMesh::VertexHandle;
    using HalfedgeHandle = CageMesh::HalfedgeHandle;

    // The mesh must have no deleted elements (garbage collected), and is left with some.
    Decimation(CageMesh& mesh, double max_normal_deviation, const LoopLimits& limits, const DecimationProgress& progress)
        : mesh_(mesh), progress_(progress), faces_(mesh.n_faces()), quadric_(mesh), guard_(mesh),
          neighbour_stamp_(mesh.n_vertices(), 0), heap_(HeapInterface{this}) {
        quadric_.initialize();
        guard_.set_limits(&limits);
        if (max_normal_deviation > 0.0) {
            flipping_.emplace(mesh);
            flipping_->set_max_normal_deviation(max_normal_deviation);
        }
    }
    Decimation(const Decimation&) = delete;
    Decimation& operator=(const Decimation&) = delete;

    std::size_t faces() const { return faces_; }

    // Multiple-choice decimation (Wu and Kobbelt, "Fast mesh decimation by multiple-choice
    // techniques", VMV 2002) down to at most `until` faces: each step draws kChoices random edges
    // and collapses the cheapest allowed of their halfedges. No heap and no neighbours' updates: it
    // evaluates kChoices edges a collapse where the heap evaluates every halfedge around about seven
    // vertices, a handful of them fully. Stops early after kMaxMisses steps in a row with nothing
    // allowed (near an irreducible mesh), leaving the rest to decimate_to_faces. Deterministic for the
    // seed (std::mt19937, not rand()'s global state as OpenMesh's McDecimaterT).
    void decimate_by_choices(std::size_t until, std::uint32_t seed) {
        std::mt19937 random(seed);
        std::vector<int> live(mesh_.n_edges());  // edges not yet seen deleted
        std::iota(live.begin(), live.end(), 0);
        std::size_t misses = 0;
        while (faces_ > until && misses < kMaxMisses && !live.empty()) {
            candidates_.clear();
            for (std::size_t drawn = 0; drawn < kChoices && !live.empty();) {
                int& edge = live[std::uniform_int_distribution<std::size_t>(0, live.size() - 1)(random)];
                const CageMesh::EdgeHandle e(edge);
                if (mesh_.status(e).deleted()) {
                    edge = live.back();
                    live.pop_back();
                    continue;
                }
                ++drawn;
                for (int side : {0, 1}) add_candidate(mesh_.halfedge_handle(e, side));
            }
            const auto chosen = std::find_if(candidates_.begin(), candidates_.end(),
                                             [&](const Candidate& c) { return allowed(CollapseInfo(mesh_, c.halfedge)); });
            if (chosen == candidates_.end()) {
                ++misses;
                continue;
            }
            misses = 0;
            collapse(CollapseInfo(mesh_, chosen->halfedge));
        }
    }

    // DecimaterT::decimate_to_faces: the same collapses in the same order (a heap of vertices, each
    // keyed by its cheapest allowed collapse, an outgoing halfedge; the cheapest taken first and its
    // one-ring's keys computed again) until at most target faces are left or no collapse is allowed.
    // Two changes made it about five times faster than DecimaterT, with the same cages byte for byte
    // (make_cage of the 940,544-triangle bunny to 5,000: 12.7 s against 59.3 s; the cage tests: 3.4 s
    // against 17.3 s, all 27 cages the same; the machine busy, 2026-12-05):
    //  - the legality test is ours, inline (collapse_legal): Debian's libOpenMeshCore is built with
    //    assertions, whose type checks construct and compare a std::string on every property lookup
    //    inside the library, so is_collapse_ok, find_halfedge and valence took 55% of the time;
    //  - a vertex's collapses are ranked by their quadric error first and tested in that order up to
    //    the first allowed one: DecimaterT tests all of them (about six), then takes the cheapest
    //    allowed, which is the same one.
    void decimate_to_faces(std::size_t target) {
        priority_.assign(mesh_.n_vertices(), 0.0f);
        heap_position_.assign(mesh_.n_vertices(), -1);
        collapse_target_.assign(mesh_.n_vertices(), HalfedgeHandle());
        heap_.reserve(mesh_.n_vertices());
        for (VertexHandle v : mesh_.vertices()) update(v);
        std::vector<VertexHandle> ring;
        while (!heap_.empty() && faces_ > target) {
            const VertexHandle v = heap_.front();
            heap_.pop_front();
            const CollapseInfo ci(mesh_, collapse_target_[index(v)]);
            if (!collapse_legal(ci)) continue;
            ring.clear();
            for (VertexHandle w : mesh_.vv_range(ci.v0)) ring.push_back(w);
            collapse(ci);
            for (VertexHandle w : ring) update(w);
        }
    }

private:
    // Edges drawn a multiple-choice step (both halfedges of each are candidates). On the bunny to
    // 5,000, 4 instead of 8 was not measurably faster and fitted a little worse (rms 0.00183 against
    // 0.00181 of the diagonal 15.6).
    static constexpr std::size_t kChoices = 8;
    static constexpr std::size_t kMaxMisses = 1000;

    struct Candidate {
        float error;
        HalfedgeHandle halfedge;
    };

    struct HeapInterface {
        Decimation* self;
        bool less(VertexHandle a, VertexHandle b) const { return self->priority_[index(a)] < self->priority_[index(b)]; }
        bool greater(VertexHandle a, VertexHandle b) const { return self->priority_[index(a)] > self->priority_[index(b)]; }
        int get_heap_position(VertexHandle v) const { return self->heap_position_[index(v)]; }
        void set_heap_position(VertexHandle v, int position) const { self->heap_position_[index(v)] = position; }
    };

    static std::size_t index(VertexHandle v) { return static_cast<std::size_t>(v.idx()); }

    void collapse(const CollapseInfo& ci) {
        faces_ -= mesh_.is_boundary(ci.v0v1) || mesh_.is_boundary(ci.v1v0) ? 1 : 2;
        mesh_.collapse(ci.v0v1);
        if (flipping_)  // the normals the next flipping tests compare with
            for (CageMesh::FaceHandle f : mesh_.vf_range(ci.v1)) mesh_.set_normal(f, mesh_.calc_face_normal(f));
        quadric_.postprocess_collapse(ci);
        // Every 1024 collapses: a few milliseconds, 457 reports for the bunny.
        if (++collapses_ % 1024 == 0) progress_.tell(faces_);
    }

    // The halfedge among the candidates by its quadric error, after those with a smaller or equal
    // one (so equal errors keep the order they came in, as DecimaterT takes them); none when the
    // error is not a priority DecimaterT would take.
    void add_candidate(HalfedgeHandle h) {
        const float error = quadric_.collapse_priority(CollapseInfo(mesh_, h));
        if (!(error >= 0.0f && error < std::numeric_limits<float>::max())) return;
        const auto after = std::upper_bound(candidates_.begin(), candidates_.end(), error,
                                            [](float e, const Candidate& c) { return e < c.error; });
        candidates_.insert(after, {error, h});
    }

    bool adjacent(VertexHandle a, VertexHandle b) const {
        for (VertexHandle w : mesh_.vv_range(a))
            if (w == b) return true;
        return false;
    }

    bool valence_three(VertexHandle v) const {
        std::size_t valence = 0;
        for (HalfedgeHandle h : mesh_.voh_range(v)) {
            static_cast<void>(h);
            if (++valence > 3) return false;
        }
        return valence == 3;
    }

    // BaseDecimaterT::is_collapse_legal, TriConnectivity::is_collapse_ok included.
    bool collapse_legal(const CollapseInfo& ci) {
        const CageMesh& m = mesh_;
        if (m.status(ci.v0).locked()) return false;
        // is_collapse_ok: live elements; no ear (a face whose other two edges are boundary); no
        // interior edge between two boundary vertices; the link condition (v0 and v1 share no
        // neighbour but vl and vr), last as the dearest.
        if (m.status(m.edge_handle(ci.v0v1)).deleted() || m.status(ci.v0).deleted() || m.status(ci.v1).deleted())
            return false;
        if (ci.fl.is_valid() && m.is_boundary(ci.vlv1) && m.is_boundary(ci.v0vl)) return false;
        if (ci.fr.is_valid() && m.is_boundary(ci.vrv0) && m.is_boundary(ci.v1vr)) return false;
        if (ci.vl == ci.vr) return false;
        const bool v0_boundary = m.is_boundary(ci.v0);
        if (v0_boundary && m.is_boundary(ci.v1) && !m.is_boundary(ci.v0v1) && !m.is_boundary(ci.v1v0)) return false;
        // The rest of is_collapse_legal: a feature vertex only along a feature edge; a boundary
        // vertex only along the boundary; v0 not of valence 2; no two valence-3 vertices vl, vr
        // joined by an edge (the collapse would fold them onto each other).
        if (m.status(ci.v0).feature() && !m.status(m.edge_handle(ci.v0v1)).feature()) return false;
        if (v0_boundary && (!m.is_boundary(ci.v1) || (ci.vl.is_valid() && ci.vr.is_valid()))) return false;
        if (m.cw_rotated_halfedge_handle(m.cw_rotated_halfedge_handle(ci.v0v1)) == ci.v0v1) return false;
        if (ci.vl.is_valid() && ci.vr.is_valid() && valence_three(ci.vl) && valence_three(ci.vr) && adjacent(ci.vl, ci.vr))
            return false;
        ++stamp_;
        for (VertexHandle w : m.vv_range(ci.v1)) neighbour_stamp_[index(w)] = stamp_;
        for (VertexHandle w : m.vv_range(ci.v0))
            if (neighbour_stamp_[index(w)] == stamp_ && w != ci.vl && w != ci.vr) return false;
        return true;
    }

    // Legal, and the binary modules allow it.
    bool allowed(const CollapseInfo& ci) {
        return collapse_legal(ci) && guard_.collapse_priority(ci) >= 0.0f &&
               (!flipping_ || flipping_->collapse_priority(ci) >= 0.0f);
    }

    // DecimaterT::heap_vertex: v's cheapest allowed collapse, or v off the heap when it has none.
    void update(VertexHandle v) {
        candidates_.clear();
        for (HalfedgeHandle h : mesh_.voh_range(v)) add_candidate(h);
        for (const Candidate& c : candidates_) {
            if (!allowed(CollapseInfo(mesh_, c.halfedge))) continue;
            collapse_target_[index(v)] = c.halfedge;
            priority_[index(v)] = c.error;
            if (heap_.is_stored(v))
                heap_.update(v);
            else
                heap_.insert(v);
            return;
        }
        if (heap_.is_stored(v)) heap_.remove(v);
    }

    CageMesh& mesh_;
    const DecimationProgress& progress_;
    std::size_t faces_;
    std::size_t collapses_ = 0;
    OpenMesh::Decimater::ModQuadricT<CageMesh> quadric_;
    ModTopologyGuardT<CageMesh> guard_;
    std::optional<OpenMesh::Decimater::ModNormalFlippingT<CageMesh>> flipping_;
    std::vector<Candidate> candidates_;
    // The link condition's marks: v1's neighbours carry the current stamp.
    std::vector<std::uint32_t> neighbour_stamp_;
    std::uint32_t stamp_ = 0;
    // The heap's keys by vertex index.
    std::vector<float> priority_;
    std::vector<int> heap_position_;
    std::vector<HalfedgeHandle> collapse_target_;
    OpenMesh::Utils::HeapT<VertexHandle, HeapInterface> heap_;
};

// One decimation pass to at most target faces; returns the faces left. Multiple choices take a large
// mesh down to 4 times the target (and no lower than 20,000 faces, so that small meshes and the last
// collapses before a stall, where the exact order matters most, stay the heap's), the heap the rest.
// On the bunny at 940,544 triangles to 5,000, whole `rgbsub remesh` (three interleaved runs each, the
// machine busy, 2026-12-05): 9.4-10.7 s of CPU against 11.0-13.3 s with the heap alone, and the
// fit as close or closer (rms 0.00181 against 0.00183 of the diagonal 15.6, max 0.0136 against 0.0154).
std::size_t decimate_pass(CageMesh& mesh, std::size_t target, double max_normal_deviation, const LoopLimits& limits,
                          std::uint32_t seed, const DecimationProgress& progress) {
    if (mesh.n_faces() <= target) return mesh.n_faces();
    {
        Decimation decimation(mesh, max_normal_deviation, limits, progress);
        const std::size_t exact_below = std::max<std::size_t>(4 * target, 20000);
        if (decimation.faces() > exact_below) decimation.decimate_by_choices(exact_below, seed);
        decimation.decimate_to_faces(target);
    }
    mesh.garbage_collection();
    return mesh.n_faces();
}

// Random edge flips until the collapses reach the target again (an irreducible triangulation has
// no legal collapse, but a flip makes one: the flip graph of a surface's triangulations with n
// vertices is connected and holds reducible ones above the minimum).
bool unstall(CageMesh& mesh, std::size_t target, const CageOptions& options, const LoopLimits& limits,
             std::uint32_t seed, const DecimationProgress& progress, std::size_t& flips) {
    std::mt19937 random(seed);
    std::size_t attempts = 0;
    while (mesh.n_faces() > target && flips < options.max_flips && attempts < 20 * options.max_flips) {
        ++attempts;
        std::uniform_int_distribution<std::size_t> pick(0, mesh.n_edges() - 1);
        const CageMesh::EdgeHandle e(static_cast<int>(pick(random)));
        if (mesh.is_boundary(e) || mesh.status(e).feature() || !mesh.is_flip_ok(e)) continue;
        mesh.flip(e);
        ++flips;
        decimate_pass(mesh, target, 0.0, limits, seed, progress);
    }
    return mesh.n_faces() <= target;
}

// M's feature edges within the component as OpenMesh's feature edges and vertices (which
// BaseDecimaterT collapses only along a feature edge), the anchors locked.
void mark_features(CageMesh& mesh, const FeatureGraph& features, std::span<const std::uint8_t> anchor,
                   const std::unordered_map<std::uint32_t, CageMesh::VertexHandle>& handle_of) {
    for (const auto& [v, h] : handle_of) {
        if (anchor[v]) mesh.status(h).set_locked(true);
        for (std::uint32_t w : features.neighbours(v)) {
            if (w < v) continue;
            const CageMesh::HalfedgeHandle e = mesh.find_halfedge(h, handle_of.at(w));
            mesh.status(mesh.edge_handle(e)).set_feature(true);
            mesh.status(h).set_feature(true);
            mesh.status(handle_of.at(w)).set_feature(true);
        }
    }
}

// One component's cage, decimated to at most part.share faces; above it (reached false) where the
// collapses and flips stalled. Checked: an oriented manifold with the component's topology.
struct ComponentCage {
    Cage cage;
    bool reached = true;
};

ComponentCage cage_component(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                             const ComponentPart& part, const CageOptions& options, std::span<const std::uint8_t> anchor,
                             std::uint32_t seed) {
    CageMesh mesh;
    mesh.request_vertex_status();
    mesh.request_edge_status();
    mesh.request_face_status();
    mesh.request_face_normals();
    OpenMesh::VPropHandleT<std::uint32_t> source;
    mesh.add_property(source);
    mesh.reserve(part.topology.vertices, part.topology.edges, part.topology.faces);
    std::unordered_map<std::uint32_t, CageMesh::VertexHandle> handle_of;
    handle_of.reserve(part.topology.vertices);
    for (std::uint32_t f : part.faces)
        for (std::uint32_t v : triangles[f])
            if (!handle_of.contains(v)) {
                const glm::dvec3& p = positions[v];
                const CageMesh::VertexHandle h = mesh.add_vertex(CageMesh::Point(p.x, p.y, p.z));
                mesh.property(source, h) = v;
                handle_of.emplace(v, h);
            }
    const DecimationProgress progress{&options.progress, part.faces.size(), part.share};
    for (std::size_t k = 0; k < part.faces.size(); ++k) {
        // Building the mesh takes seconds for a million faces on a busy machine: stops are heard.
        if (k % 65536 == 0) progress.tell(part.faces.size());
        const std::uint32_t f = part.faces[k];
        const rgb::Triangle& t = triangles[f];
        if (!mesh.add_face(handle_of.at(t[0]), handle_of.at(t[1]), handle_of.at(t[2])).is_valid())
            throw std::logic_error("OpenMesh refused face " + std::to_string(f) + " of a validated manifold mesh");
    }
    mesh.update_face_normals();
    if (options.features != nullptr) mark_features(mesh, *options.features, anchor, handle_of);

    // Each boundary loop keeps at least 3 edges (more for a surface of positive genus, below).
    LoopLimits limits;
    mesh.add_property(limits.loop);
    for (CageMesh::VertexHandle v : mesh.vertices()) mesh.property(limits.loop, v) = -1;
    for (CageMesh::HalfedgeHandle h : mesh.halfedges()) {
        if (!mesh.is_boundary(h) || mesh.property(limits.loop, mesh.to_vertex_handle(h)) >= 0) continue;
        const int loop = static_cast<int>(limits.min_edges.size());
        limits.min_edges.push_back(3);
        auto g = h;
        do {
            mesh.property(limits.loop, mesh.to_vertex_handle(g)) = loop;
            g = mesh.next_halfedge_handle(g);
        } while (g != h);
    }
    if (!limits.min_edges.empty() && part.topology.genus() > 0) {
        // Collapses only shorten the loops and a cage with every vertex on the boundary has
        // F = Eb - 2χ, so the loops keep what such a cage of the share would have, but no more than
        // the smallest cage's vertices and two a loop (the bound may not be attained: a torus with
        // two holes needs 12 triangles on 8 vertices, not the bound's 11 on 7), handed out in turn.
        const long b = static_cast<long>(limits.min_edges.size());
        const long smallest_vertices = static_cast<long>(part.smallest) + 2 * part.topology.euler;
        const long keep = std::min(static_cast<long>(part.share) + 2 * part.topology.euler, smallest_vertices + 2 * b);
        for (long extra = keep - 3 * b, k = 0; extra > 0; --extra, k = (k + 1) % b)
            ++limits.min_edges[static_cast<std::size_t>(k)];
    }

    progress.tell(part.faces.size());
    std::size_t faces = decimate_pass(mesh, part.share, options.max_normal_deviation_degrees, limits, seed, progress);
    if (faces > part.share) faces = decimate_pass(mesh, part.share, 0.0, limits, seed, progress);
    ComponentCage out;
    if (faces > part.share) out.reached = unstall(mesh, part.share, options, limits, seed, progress, out.cage.flips);

    // Out: the component's cage, checked.
    Cage& cage = out.cage;
    for (CageMesh::VertexHandle v : mesh.vertices()) {
        const CageMesh::Point& p = mesh.point(v);
        cage.positions.emplace_back(p[0], p[1], p[2]);
        cage.source_vertex.push_back(mesh.property(source, v));
    }
    for (CageMesh::EdgeHandle e : mesh.edges())
        if (mesh.status(e).feature()) {
            const auto a = static_cast<std::uint32_t>(mesh.to_vertex_handle(mesh.halfedge_handle(e, 0)).idx());
            const auto b = static_cast<std::uint32_t>(mesh.to_vertex_handle(mesh.halfedge_handle(e, 1)).idx());
            cage.feature_edges.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(cage.feature_edges.begin(), cage.feature_edges.end());
    cage.triangles.reserve(mesh.n_faces());
    for (CageMesh::FaceHandle f : mesh.faces()) {
        rgb::Triangle t{};
        int i = 0;
        for (CageMesh::VertexHandle v : mesh.fv_range(f)) t[i++] = static_cast<std::uint32_t>(v.idx());
        cage.triangles.push_back(t);
    }
    if (auto problem = manifold_problem(cage.positions.size(), cage.triangles))
        throw std::logic_error("the decimated cage is not an oriented manifold: " + *problem);
    MeshTopology want;
    want.components.push_back(part.topology);
    if (auto mismatch = topology_mismatch(want, topology_of(cage.positions, cage.triangles)))
        throw std::logic_error("the decimation changed a component's topology: " + *mismatch);
    return out;
}

// Shares of the target proportional to area, each at least the component's smallest count and at
// most its own face count (water filling: components pinned at a bound leave the rest to the others).
void share_target(std::vector<ComponentPart>& parts, std::size_t target) {
    std::vector<bool> pinned(parts.size(), false);
    double budget = static_cast<double>(target);
    for (;;) {
        double area = 0.0;
        for (std::size_t i = 0; i < parts.size(); ++i)
            if (!pinned[i]) area += parts[i].topology.area;
        const double scale = area > 0.0 ? budget / area : 0.0;
        bool changed = false;
        for (std::size_t i = 0; i < parts.size(); ++i)  // raise to the minimum first
            if (!pinned[i] && scale * parts[i].topology.area < static_cast<double>(parts[i].smallest)) {
                pinned[i] = true;
                parts[i].share = parts[i].smallest;
                budget -= static_cast<double>(parts[i].share);
                changed = true;
            }
        if (changed) continue;
        for (std::size_t i = 0; i < parts.size(); ++i)
            if (!pinned[i] && scale * parts[i].topology.area >= static_cast<double>(parts[i].topology.faces)) {
                pinned[i] = true;
                parts[i].share = parts[i].topology.faces;
                budget -= static_cast<double>(parts[i].share);
                changed = true;
            }
        if (changed) continue;
        for (std::size_t i = 0; i < parts.size(); ++i)
            if (!pinned[i])
                parts[i].share = std::max(parts[i].smallest,
                                          static_cast<std::size_t>(std::floor(scale * parts[i].topology.area)));
        return;
    }
}

}  // namespace

Cage make_cage(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
               std::size_t target_triangles, const CageOptions& given_options) {
    // Each component's decimation tells its share; the caller is told the whole's, each component
    // weighed by its face count.
    std::size_t faces_before = 0, component_faces = 0;
    CageOptions options = given_options;
    if (given_options.progress)
        options.progress = [&](double share) {
            return given_options.progress((static_cast<double>(faces_before) + share * static_cast<double>(component_faces)) /
                                          static_cast<double>(triangles.size()));
        };
    if (triangles.empty()) throw std::invalid_argument("cannot build a cage of an empty mesh (no triangles)");
    if (triangles.size() == 1) throw std::invalid_argument("cannot build a cage of a single triangle");
    if (auto problem = manifold_problem(positions.size(), triangles))
        throw std::invalid_argument("cannot build a cage: not an oriented manifold triangle mesh: " + *problem);
    report_share(options.progress, 0.0);  // each check of a million triangles takes a fraction of a second
    double area = 0.0;
    for (const rgb::Triangle& t : triangles) {
        for (std::uint32_t v : t)
            if (!std::isfinite(positions[v].x) || !std::isfinite(positions[v].y) || !std::isfinite(positions[v].z))
                throw std::invalid_argument("cannot build a cage: vertex " + std::to_string(v) +
                                            " has a non-finite position");
        area += triangle_area(positions, t);
    }
    if (!(area > 0.0))
        throw std::invalid_argument("cannot build a cage of a degenerate mesh: every triangle has zero area");

    std::vector<ComponentPart> parts = split_components(positions, triangles);
    report_share(options.progress, 0.0);
    std::size_t smallest = 0;
    for (ComponentPart& part : parts) {
        part.smallest = smallest_component_triangles(part.topology.genus(), part.topology.boundary_loops);
        smallest += part.smallest;
    }
    if (target_triangles < smallest) {
        MeshTopology topology;
        for (const ComponentPart& part : parts) topology.components.push_back(part.topology);
        std::sort(topology.components.begin(), topology.components.end(), canonical_before);
        std::string what;
        for (const ComponentTopology& c : topology.components)
            what += (what.empty() ? "" : ", ") + describe(c);
        throw std::invalid_argument("a cage of " + std::to_string(target_triangles) +
                                    " triangles is too few for this mesh's topology (" + what +
                                    "): the smallest is " + std::to_string(smallest) + " triangles");
    }

    const std::size_t budget = std::min(target_triangles, triangles.size());
    if (target_triangles >= triangles.size()) {
        for (ComponentPart& part : parts) part.share = part.faces.size();  // the mesh as it is
    } else {
        share_target(parts, budget);
    }
    std::vector<std::uint8_t> anchor;
    if (options.features != nullptr) {
        if (options.features->num_vertices() != positions.size())
            throw std::invalid_argument("make_cage: the features are of a mesh with another vertex count");
        anchor.assign(positions.size(), 0);
        for (std::uint32_t v : feature_anchors(*options.features)) anchor[v] = 1;
    }
    std::vector<ComponentCage> cages;
    const auto seed_of = [&](std::size_t i) { return options.seed + static_cast<std::uint32_t>(i) * 7919u; };
    for (std::size_t i = 0; i < parts.size(); ++i) {
        component_faces = parts[i].faces.size();
        report_share(options.progress, 0.0);
        cages.push_back(cage_component(positions, triangles, parts[i], options, anchor, seed_of(i)));
        // Stalled: the smallest share above that it reaches (a few tries; each is a decimation).
        const std::size_t share = parts[i].share;
        for (std::size_t more = 1; !cages[i].reached && more <= 4 && share + more < cages[i].cage.triangles.size();
             ++more) {
            ComponentPart larger = parts[i];
            larger.share = share + more;
            ComponentCage retry = cage_component(positions, triangles, larger, options, anchor, seed_of(i));
            if (retry.reached) {
                parts[i].smallest = std::max(parts[i].smallest, larger.share);
                cages[i] = std::move(retry);
                cages[i].reached = false;  // above its share: the others give up the excess
            }
        }
        faces_before += component_faces;
    }
    component_faces = 0;  // what follows is small: the whole is done, stops still heard

    // A component that stalled above its share (a bordered surface of positive genus can need more
    // than smallest_component_triangles' bound) takes the excess from the others, down to their
    // smallest counts; when they cannot give it, the target is refused with the count that works.
    const auto total = [&] {
        std::size_t sum = 0;
        for (const ComponentCage& c : cages) sum += c.cage.triangles.size();
        return sum;
    };
    for (std::size_t round = 0; round <= parts.size() && total() > budget; ++round) {
        std::size_t excess = total() - budget;
        bool changed = false;
        for (std::size_t i = 0; i < parts.size() && excess > 0; ++i) {
            const std::size_t faces = cages[i].cage.triangles.size();
            if (!cages[i].reached || faces <= parts[i].smallest) continue;
            const std::size_t give = std::min(excess, faces - parts[i].smallest);
            ComponentPart smaller = parts[i];
            smaller.share = faces - give;
            ComponentCage retry = cage_component(positions, triangles, smaller, options, anchor, seed_of(i));
            const std::size_t now = retry.cage.triangles.size();
            if (now < faces) {
                excess -= std::min(excess, faces - now);
                parts[i] = smaller;
                cages[i] = std::move(retry);
                changed = true;
            } else {
                cages[i].reached = false;  // gives nothing: leave it as it was
            }
        }
        if (!changed) break;
    }
    if (total() > budget) {
        std::size_t works = 0;
        for (std::size_t i = 0; i < parts.size(); ++i)
            works += cages[i].reached ? parts[i].smallest : cages[i].cage.triangles.size();
        throw std::invalid_argument("a cage of " + std::to_string(target_triangles) +
                                    " triangles is too few for this mesh: the decimation stalls above it (the "
                                    "topology's bound is " + std::to_string(smallest) +
                                    "); the smallest that works here is " + std::to_string(works) + " triangles");
    }

    Cage cage;
    for (const ComponentCage& c : cages) {
        const auto offset = static_cast<std::uint32_t>(cage.positions.size());
        cage.positions.insert(cage.positions.end(), c.cage.positions.begin(), c.cage.positions.end());
        cage.source_vertex.insert(cage.source_vertex.end(), c.cage.source_vertex.begin(), c.cage.source_vertex.end());
        for (rgb::Triangle t : c.cage.triangles) cage.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        for (const auto& [a, b] : c.cage.feature_edges) cage.feature_edges.push_back({a + offset, b + offset});
        cage.flips += c.cage.flips;
    }
    return cage;
}

}  // namespace rgbdetail
