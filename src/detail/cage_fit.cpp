#include "detail/cage_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>

#include "detail/loop_stencils.h"
#include "rgb/support/parallel.h"

namespace rgbdetail {

namespace {
namespace fit_internal {

using DenseXYZ = Eigen::Matrix<double, Eigen::Dynamic, 3>;

// The umbrella Laplacian of the control net (cage_fit.h): interior rows v - mean(ring), boundary rows
// v - mean(two boundary neighbours).
StencilMatrix umbrella_laplacian(const LoopTopology& topology) {
    return ring_mask_matrix(topology, [](bool boundary, int valence) {
        return RingMask{1.0, boundary ? -0.5 : -1.0 / static_cast<double>(valence)};
    });
}

}  // namespace fit_internal
}  // namespace

FitResult fit_cage(const std::vector<glm::dvec3>& cage_positions, const std::vector<rgb::Triangle>& cage_triangles,
                   const TargetFunction& closest_on_m, const FitOptions& options) {
    if (options.iterations < 0) throw std::invalid_argument("fit_cage: iterations must be >= 0");
    if (options.sample_level < 0 || options.sample_level > 4)
        throw std::invalid_argument("fit_cage: sample_level must be in 0-4");
    if (!(options.lambda >= 0.0) || !std::isfinite(options.lambda))
        throw std::invalid_argument("fit_cage: lambda must be finite and >= 0");
    if (!closest_on_m) throw std::invalid_argument("fit_cage: no closest-point function");

    const std::size_t n = cage_positions.size();
    const LoopTopology topology(n, cage_triangles);
    const LoopStencils stencils = limit_stencils(n, cage_triangles, options.sample_level);
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
        if (options.parallel_targets)
            rgb::parallel_for(m, 256, find);
        else
            find(0, m);
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
