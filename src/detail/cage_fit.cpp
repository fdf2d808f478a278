#include "detail/cage_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/SparseCholesky>

#include "detail/loop_stencils.h"
#include "rgb/support/parallel.h"

namespace rgbdetail {

namespace {
namespace fit_internal {

using DenseXYZ = Eigen::Matrix<double, Eigen::Dynamic, 3>;

// The umbrella Laplacian of the control net (cage_fit.h), row v: v - mean(the neighbours that shape
// the surface at v). Those are v's whole ring where the surface is smooth (smooth and dart vertices),
// only its two crease neighbours at a crease vertex (a boundary vertex is one, with its boundary
// neighbours), and none at a corner, whose row is empty. Smoothing a crease vertex over its whole
// ring would pull it off the crease towards the faces on either side and round the sharp edge the
// tags keep; a corner is the end of several creases, so no mean of neighbours is a shape it should
// tend to, and the samples alone place it.
StencilMatrix umbrella_laplacian(const LoopTopology& topology) {
    const std::size_t n = topology.num_vertices();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(8 * n);
    for (std::uint32_t v = 0; v < n; ++v) {
        const rgb::VertexRule rule = topology.rule(v);
        if (rule == rgb::VertexRule::Corner) continue;
        const bool along_creases = rule == rgb::VertexRule::Crease;
        const std::vector<std::uint32_t> creases = along_creases ? topology.sharp_neighbours(v) : std::vector<std::uint32_t>{};
        const std::span<const std::uint32_t> neighbours = along_creases ? std::span<const std::uint32_t>(creases) : topology.ring(v);
        const auto row = static_cast<Eigen::Index>(v);
        entries.emplace_back(row, v, 1.0);
        for (std::uint32_t w : neighbours) entries.emplace_back(row, w, -1.0 / static_cast<double>(neighbours.size()));
    }
    StencilMatrix lap(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    lap.setFromTriplets(entries.begin(), entries.end());
    return lap;
}

}  // namespace fit_internal
}  // namespace

FitResult fit_cage(const std::vector<glm::dvec3>& cage_positions, const std::vector<rgb::Triangle>& cage_triangles,
                   const rgb::SharpFeatures& cage_features, const TargetFunction& closest_on_m, const FitOptions& options) {
    if (options.iterations < 0) throw std::invalid_argument("fit_cage: iterations must be >= 0");
    if (options.sample_level < 0 || options.sample_level > 4)
        throw std::invalid_argument("fit_cage: sample_level must be in 0-4");
    if (!(options.lambda >= 0.0) || !std::isfinite(options.lambda))
        throw std::invalid_argument("fit_cage: lambda must be finite and >= 0");
    if (!closest_on_m) throw std::invalid_argument("fit_cage: no closest-point function");

    const std::size_t n = cage_positions.size();
    const LoopTopology topology(n, cage_triangles, cage_features);
    const LoopStencils stencils = limit_stencils(n, cage_triangles, cage_features, options.sample_level);
    report_share(options.progress, 0.0);  // the stencils and the factorization take a fraction of a second each
    // Column-major copies for the products A^T x (a row-major A would be transposed on the fly).
    const Eigen::SparseMatrix<double> a = stencils.limit;
    const Eigen::SparseMatrix<double> lap = fit_internal::umbrella_laplacian(topology);
    const std::size_t m = static_cast<std::size_t>(a.rows());

    const double lambda_eff = options.lambda * static_cast<double>(m) / static_cast<double>(n);
    const Eigen::SparseMatrix<double> normal =
        Eigen::SparseMatrix<double>(a.transpose() * a) + lambda_eff * Eigen::SparseMatrix<double>(lap.transpose() * lap);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success)
        throw std::runtime_error("fit_cage: the normal equations could not be factored (lambda 0 on a cage the samples do not determine?)");
    report_share(options.progress, 0.0);

    fit_internal::DenseXYZ p(static_cast<Eigen::Index>(n), 3);
    for (std::size_t i = 0; i < n; ++i)
        p.row(static_cast<Eigen::Index>(i)) << cage_positions[i].x, cage_positions[i].y, cage_positions[i].z;

    FitResult result;
    result.samples = m;
    fit_internal::DenseXYZ samples(static_cast<Eigen::Index>(m), 3);
    fit_internal::DenseXYZ targets(static_cast<Eigen::Index>(m), 3);
    std::vector<double> squared(m);
    for (int iteration = 0;; ++iteration) {
        samples = a * p;
        auto find = [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const auto r = static_cast<Eigen::Index>(i);
                const glm::dvec3 s(samples(r, 0), samples(r, 1), samples(r, 2));
                const glm::dvec3 t = closest_on_m(s);
                targets.row(r) << t.x, t.y, t.z;
                const glm::dvec3 d = t - s;
                squared[i] = d.x * d.x + d.y * d.y + d.z * d.z;
            }
        };
        // The passes share the fit's progress; a chunk of 8192 closest points takes a few tens of
        // milliseconds.
        const ProgressFunction pass_progress =
            part_of(options.progress, static_cast<double>(iteration) / (options.iterations + 1),
                    static_cast<double>(iteration + 1) / (options.iterations + 1));
        in_chunks(m, 8192, pass_progress, [&](std::size_t begin, std::size_t end) {
            if (options.parallel_targets)
                rgb::parallel_for(end - begin, 256, [&](std::size_t b, std::size_t e) { find(begin + b, begin + e); });
            else
                find(begin, end);
        });
        FitDistances distances;
        double sum = 0.0;
        for (double s : squared) {
            sum += s;
            distances.max = std::max(distances.max, s);
        }
        distances.rms = m > 0 ? std::sqrt(sum / static_cast<double>(m)) : 0.0;
        distances.max = std::sqrt(distances.max);
        result.distances.push_back(distances);
        if (iteration == options.iterations) break;

        const fit_internal::DenseXYZ rhs = a.transpose() * targets;
        p = solver.solve(rhs);
        if (solver.info() != Eigen::Success) throw std::runtime_error("fit_cage: the solve failed");
    }

    result.positions.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        result.positions[i] = glm::dvec3(p(r, 0), p(r, 1), p(r, 2));
    }
    return result;
}

}  // namespace rgbdetail
