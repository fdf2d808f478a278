#include "app/request_pieces.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <glm/geometric.hpp>

#include "rgb/mesh/base_face_index.h"
#include "rgb/mesh/mesh.h"

namespace app {
namespace {

// Triangles a refine request may add (rgb::estimated_triangles).
double added(const rgb::Mesh& mesh, const rgb::LevelRequest& request) {
    return request.kind == rgb::RequestKind::Coarsen ? 0.0 : rgb::estimated_triangles(mesh, request) - static_cast<double>(mesh.num_faces());
}

// Triangles there are in the region the request searches: estimated as for a refine to the mesh's
// average level. Coarsening searches a triangle's size of level N around its ball (requests.cpp).
double present(const rgb::Mesh& mesh, const rgb::LevelRequest& request) {
    const double per_base_face = static_cast<double>(mesh.num_faces()) / static_cast<double>(std::max<std::size_t>(mesh.base().num_faces(), 1));
    rgb::LevelRequest average = request;
    average.kind = rgb::RequestKind::Refine;
    average.level = std::clamp(static_cast<int>(std::lround(std::log2(std::max(per_base_face, 1.0)) / 2.0)), 0, rgb::kMaxLevel);
    average.taper.clear();
    if (average.sphere && request.kind != rgb::RequestKind::Refine) {
        for (const rgb::LevelBand& band : request.taper) average.sphere->radius = std::max(average.sphere->radius, band.radius);
        average.sphere->radius += std::ldexp(mesh.base().longest_edge(), -request.level);
    }
    return added(mesh, average);
}

// A triangle coarsening visits costs about eight times one refining makes (half a vertex removal
// each: a merge, its swaps and the search for what depends on it), measured with
// tests/bench/brush_bench at 3.6M triangles.
constexpr double kRemovalWork = 8.0;

// What a request costs: it visits the triangles there (and may remove them) and makes the ones it adds.
double expected_work(const rgb::Mesh& mesh, const rgb::LevelRequest& request) {
    return (request.kind == rgb::RequestKind::Refine ? 1.0 : kRemovalWork) * present(mesh, request) + added(mesh, request);
}

// `request` over consecutive batches of its base faces, each of about `per_piece` expected work.
void append_batches(const rgb::Mesh& mesh, const rgb::LevelRequest& request, double per_piece, std::vector<rgb::LevelRequest>& out) {
    const std::vector<std::uint32_t> faces = request_base_faces(mesh, request);
    if (faces.empty()) return;
    const double work = expected_work(mesh, request);
    const auto batches = static_cast<std::size_t>(std::clamp(std::ceil(work / per_piece), 1.0, static_cast<double>(faces.size())));
    const std::size_t per_batch = (faces.size() + batches - 1) / batches;
    for (std::size_t first = 0; first < faces.size(); first += per_batch) {
        rgb::LevelRequest piece = request;
        piece.base_faces.assign(faces.begin() + static_cast<std::ptrdiff_t>(first),
                                faces.begin() + static_cast<std::ptrdiff_t>(std::min(first + per_batch, faces.size())));
        out.push_back(std::move(piece));
    }
}

// Refine to level k: the ball of the band of level k (the widest one asking k or more), the finer
// bands capped at k, the coarser ones kept.
rgb::LevelRequest refine_to(const rgb::LevelRequest& request, int k) {
    rgb::LevelRequest piece = request;
    piece.kind = rgb::RequestKind::Refine;
    piece.level = k;
    piece.taper.clear();
    for (const rgb::LevelBand& band : request.taper) {
        if (band.level < k) piece.taper.push_back(band);
        else if (piece.sphere) piece.sphere->radius = std::max(piece.sphere->radius, band.radius);
    }
    return piece;
}

// Coarse to fine: the coarsen part first (set requests), then the refine part level by level from
// just above `from_level`, each level that adds at least as many triangles as its pass over the
// region visits (a piece also does what skipped coarser pieces would have: skipping them only saves
// their pass over the faces).
std::vector<rgb::LevelRequest> pieces_of(const rgb::Mesh& mesh, const rgb::LevelRequest& request, double per_piece, int from_level) {
    std::vector<rgb::LevelRequest> pieces;
    if (request.kind != rgb::RequestKind::Refine) {
        rgb::LevelRequest coarsen = request;
        coarsen.kind = rgb::RequestKind::Coarsen;
        append_batches(mesh, coarsen, per_piece, pieces);
    }
    if (request.kind == rgb::RequestKind::Coarsen) return pieces;
    const double there = present(mesh, request);
    for (int k = std::clamp(from_level + 1, 1, request.level); k <= request.level; ++k) {
        const rgb::LevelRequest piece = refine_to(request, k);
        if (k == request.level || added(mesh, piece) >= there) append_batches(mesh, piece, per_piece, pieces);
    }
    return pieces;
}

}  // namespace

std::vector<std::uint32_t> request_base_faces(const rgb::Mesh& mesh, const rgb::LevelRequest& request) {
    std::vector<std::uint32_t> faces;
    if (request.sphere) {
        double radius = request.sphere->radius;
        for (const rgb::LevelBand& band : request.taper) radius = std::max(radius, band.radius);
        faces = mesh.base().face_index().faces_meeting_sphere(request.sphere->centre, radius);
    } else {
        faces.resize(mesh.base().num_faces());
        for (std::uint32_t f = 0; f < faces.size(); ++f) faces[f] = f;
    }
    if (request.base_faces.empty()) return faces;
    std::vector<std::uint32_t> allowed;
    std::set_intersection(faces.begin(), faces.end(), request.base_faces.begin(), request.base_faces.end(), std::back_inserter(allowed));
    return allowed;
}

std::vector<rgb::LevelRequest> dab_pieces(const rgb::Mesh& mesh, const rgb::Dab& dab, int from_level, double piece_triangles) {
    // What apply_dab does nothing for.
    if (dab.view && !(glm::length(*dab.view) > 0.0)) return {};
    const rgb::LevelRequest request = rgb::dab_request(mesh, dab);
    if (request.sphere->radius <= 0.0 || (dab.view && request.base_faces.empty())) return {};
    if (dab.mode == rgb::BrushMode::Refine && dab.level == 0) return {};
    if (expected_work(mesh, request) <= piece_triangles) return {request};
    return pieces_of(mesh, request, piece_triangles, from_level);
}

std::vector<rgb::LevelRequest> set_all_pieces(const rgb::Mesh& mesh, int level, double piece_triangles) {
    rgb::LevelRequest request;
    request.kind = rgb::RequestKind::Set;
    request.level = level;
    int coarsest = rgb::kMaxLevel;
    for (rgb::FaceId f : mesh.faces()) coarsest = std::min(coarsest, mesh.level(f));
    return pieces_of(mesh, request, piece_triangles, coarsest);
}

}  // namespace app
