#include "detail/cage.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "detail/decimation.h"

namespace rgbdetail {
namespace {

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
