// Memory bounded before the work starts (issue 30 item 4): each path's default --max-triangles is the
// machine's memory over what a triangle costs on it (and, for a path that saves, over what loading
// the file back costs), and a max-edge or tolerance request whose result cannot fit is refused from
// an estimate made before any work, within seconds, with exit code 3.
#include <unistd.h>

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "io/mesh_file.h"
#include "io/script/detail_edit.h"
#include "io/script/triangle_limit.h"
#include "obj_test_support.h"
#include "rgb/mesh/mesh.h"
#include "run_rgbsub.h"
#include "scratch_folder.h"

namespace {

using cli_test::Outcome;
using cli_test::run_rgbsub;

class MemoryLimits : public rgbio::test::ScratchFolder {
protected:
    std::string octahedron() const {
        write("octahedron.obj", rgbio::test::kOctahedron);
        return path("octahedron.obj");
    }
};

// Three quarters of the physical memory over the bytes per triangle, computed here from sysconf.
std::size_t expected_limit(std::size_t bytes) {
    const double memory = 0.75 * double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGESIZE));
    return static_cast<std::size_t>(memory / double(bytes));
}

std::string limit_text(std::size_t limit) { return "more than the limit of " + std::to_string(limit) + " "; }

// Before: a tolerance of 1e-300 (and a max-edge of 1e-300) ran for tens of minutes toward the OOM
// killer. The timeout turns a hang into a failure.
TEST_F(MemoryLimits, AnUnreachableToleranceOrEdgeLengthIsRefusedAtOnce) {
    const std::string in = octahedron();
    for (const auto& [option, use] : {std::pair{"--tolerance", rgbio::MemoryUse::Tolerance}, std::pair{"--max-edge", rgbio::MemoryUse::MaxEdge}}) {
        const Outcome run = run_rgbsub({"refine", in, "-o", path("out.obj"), option, "1e-300"}, "timeout 30");
        EXPECT_EQ(run.exit_code, cli::exit_io_failure) << option << ": " << run.output;
        EXPECT_NE(run.output.find(limit_text(rgbio::default_triangle_limit(use))), std::string::npos) << run.output;
        EXPECT_FALSE(std::filesystem::exists(path("out.obj")));
    }
    write("script.txt", "level 1\ntolerance 1e-300\n");
    const Outcome run = run_rgbsub({"apply", in, path("script.txt"), "-o", path("out.obj")}, "timeout 30");
    EXPECT_EQ(run.exit_code, cli::exit_io_failure) << run.output;
    EXPECT_NE(run.output.find(limit_text(expected_limit(rgbio::bytes_per_triangle(rgbio::MemoryUse::Tolerance)))), std::string::npos)
        << run.output;
}

// The default of every saving path is over what loading its file back costs when that is more, so
// that refine --level never writes a file too big to load on the same machine.
TEST_F(MemoryLimits, DefaultLimitsFollowEachPathsCostAndTheCostOfLoadingBack) {
    const std::size_t load = rgbio::bytes_per_triangle(rgbio::MemoryUse::Load);
    const std::size_t level = expected_limit(std::max(rgbio::bytes_per_triangle(rgbio::MemoryUse::Level), load));
    EXPECT_EQ(rgbio::default_triangle_limit(rgbio::MemoryUse::Level), level);
    EXPECT_LE(level, expected_limit(load));
    EXPECT_EQ(rgbio::default_triangle_limit(rgbio::MemoryUse::ScreenLod), expected_limit(rgbio::bytes_per_triangle(rgbio::MemoryUse::ScreenLod)));
    for (const rgbio::MemoryUse use : {rgbio::MemoryUse::MaxEdge, rgbio::MemoryUse::Tolerance, rgbio::MemoryUse::Budget, rgbio::MemoryUse::Remesh})
        EXPECT_LE(rgbio::default_triangle_limit(use), expected_limit(load));

    const Outcome run = run_rgbsub({"refine", octahedron(), "-o", path("out.obj"), "--level", "20"});
    EXPECT_EQ(run.exit_code, cli::exit_io_failure) << run.output;
    EXPECT_NE(run.output.find(limit_text(level)), std::string::npos) << run.output;
}

// The estimate is a lower one (a request it refuses could not have fit) and a useful one (within a
// factor 64, the two levels of margin and one more, of what the request makes).
TEST_F(MemoryLimits, TheDetailEstimateIsBelowTheResultAndNearIt) {
    const rgb::Mesh base = rgbio::load_mesh(octahedron());
    for (const auto& [criterion, amount] : {std::pair{rgbio::DetailCriterion::MaxEdge, 0.1}, std::pair{rgbio::DetailCriterion::MaxEdge, 0.02},
                                            std::pair{rgbio::DetailCriterion::Tolerance, 1e-2}}) {
        rgb::Mesh mesh = base;
        rgbio::DetailEdit edit{criterion, rgbio::Amount{amount, false}, rgb::RequestKind::Set, std::nullopt};
        const double estimate = rgb::estimated_detail_triangles(mesh, rgbio::detail_request(mesh, edit, 1'000'000));
        rgbio::apply_detail_edit(mesh, edit, 1'000'000);
        SCOPED_TRACE(std::to_string(amount) + ": estimate " + std::to_string(estimate) + ", made " + std::to_string(mesh.num_faces()));
        EXPECT_LE(estimate, double(mesh.num_faces()));
        EXPECT_GE(64 * estimate, double(mesh.num_faces()));
    }
}

}  // namespace
