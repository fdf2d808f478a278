// refine --max-edge / --tolerance and the script lines max-edge / tolerance: the same meshes as the
// core's detail requests (lengths as a percentage of the bounding-box diagonal converted here),
// the tolerance reached printed and true of the saved file, and bad values refused with the
// README's exit codes and FILE:LINE messages.
#include <cmath>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "cli/dispatch.h"
#include "io/obj_reader.h"
#include "io/script/lod_script.h"
#include "obj_test_support.h"
#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"
#include "scratch_folder.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

class CliDetail : public test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        write("octahedron.obj", test::kOctahedron);
    }
    static int run(std::vector<std::string> args) { return cli::dispatch(args); }
    rgb::Mesh saved(const std::string& name) { return std::move(*read_obj_file(path(name)).adaptive); }
    static rgb::Mesh octahedron() {
        const LoadedMesh m = read_obj_text(test::kOctahedron, "octahedron.obj");
        return rgb::Mesh(m.positions, m.triangles);
    }
};

// The octahedron's bounding box is [-1, 1]^3.
const double kDiagonal = 2.0 * std::sqrt(3.0);

rgb::Mesh requested(rgb::Mesh mesh, rgb::EdgeValue value, double threshold) {
    rgb::DetailRequest request;
    request.value = std::move(value);
    request.threshold = threshold;
    rgb::apply_detail_request(mesh, request);
    return mesh;
}

TEST_F(CliDetail, MaxEdgeInPercentIsTheCoreRequestInWorldUnits) {
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("refined.obj"), "--max-edge", "8%"}), 0);
    write("script.txt", "# as a script line\nmax-edge 8%\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("applied.obj")}), 0);
    rgb::Mesh base = octahedron();
    const rgb::Mesh expected = requested(base, rgb::edge_length_value(base.shared_base()), 0.08 * kDiagonal);
    EXPECT_EQ(expected.num_faces(), 8u * 16u);  // the symmetric octahedron: uniform level 2
    EXPECT_TRUE(rgbtest::same_mesh(saved("refined.obj"), expected));
    EXPECT_TRUE(rgbtest::same_mesh(saved("applied.obj"), expected));
    // In a ball: only there.
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("ball.obj"), "--max-edge", "0.2", "--sphere", "1,0,0,0.5"}), 0);
    const rgb::Mesh ball = saved("ball.obj");
    EXPECT_GT(ball.num_faces(), 8u);
    EXPECT_LT(ball.num_faces(), requested(octahedron(), rgb::edge_length_value(base.shared_base()), 0.2).num_faces());
}

TEST_F(CliDetail, ToleranceIsReachedAndPrinted) {
    ::testing::internal::CaptureStdout();
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("refined.obj"), "--tolerance", "0.002"}), 0);
    const std::string out = ::testing::internal::GetCapturedStdout();
    const rgb::Mesh result = saved("refined.obj");
    const double reached = rgb::displayed_surface_error(result).max_error;
    EXPECT_LE(reached, 0.002);
    EXPECT_NE(out.find(std::to_string(result.num_faces()) + " triangles, maximum error "), std::string::npos) << out;
    EXPECT_NE(out.find("(tolerance 0.002)"), std::string::npos) << out;
    rgb::Mesh base = octahedron();
    EXPECT_TRUE(rgbtest::same_mesh(result, requested(base, rgb::limit_error_value(base.shared_base(), 0.002), 0.002)));
    write("script.txt", "level 3\ntolerance 0.05%\n");
    ::testing::internal::CaptureStdout();
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("applied.obj")}), 0);
    const std::string applied_out = ::testing::internal::GetCapturedStdout();
    EXPECT_NE(applied_out.find("script.txt:2: tolerance 0.05%: maximum error "), std::string::npos) << applied_out;
    EXPECT_LE(rgb::displayed_surface_error(saved("applied.obj")).max_error, 0.0005 * kDiagonal);
}

// A ball's line may end in refine or coarsen (the editor's detail-size dabs write them): the core's
// request of that kind; format_detail_line writes lines that read back to the same edit.
TEST_F(CliDetail, BallLinesTakeAKindAndTheFormatterRoundTrips) {
    const rgb::Sphere ball{{0.7, 0.2, 0.1}, 0.45};
    rgb::Mesh base = octahedron();
    rgbtest::set_level(base, 3);
    for (const rgb::RequestKind kind : {rgb::RequestKind::Refine, rgb::RequestKind::Coarsen, rgb::RequestKind::Set}) {
        DetailEdit edit;
        edit.criterion = DetailCriterion::MaxEdge;
        // Not short decimals: the line must still hold them exactly. Level 3's edges are about 0.18
        // long, their parents about 0.35: refining to 1/30 adds detail, coarsening to 0.4 removes it.
        edit.amount = {kind == rgb::RequestKind::Coarsen ? 1.2 / 3.0 : 0.1 / 3.0, false};
        edit.kind = kind;
        edit.sphere = ball;
        const std::string line = format_detail_line(edit);
        SCOPED_TRACE(line);
        const std::vector<ScriptLine> parsed = parse_lod_script(line + "\n", "detail.txt");
        ASSERT_EQ(parsed.size(), 1u);
        const DetailEdit& back = std::get<DetailEdit>(parsed[0].edit);
        EXPECT_EQ(back.criterion, edit.criterion);
        EXPECT_EQ(back.amount.value, edit.amount.value);
        EXPECT_FALSE(back.amount.percent);
        EXPECT_EQ(back.kind, kind);
        ASSERT_TRUE(back.sphere.has_value());
        EXPECT_EQ(back.sphere->centre, ball.centre);
        EXPECT_EQ(back.sphere->radius, ball.radius);

        rgb::Mesh by_script = base;
        ScriptRunner().run(by_script, parsed[0]);
        rgb::Mesh by_request = base;
        rgb::DetailRequest request;
        request.kind = kind;
        request.value = rgb::edge_length_value(by_request.shared_base());
        request.threshold = edit.amount.value;
        request.sphere = ball;
        rgb::apply_detail_request(by_request, request);
        EXPECT_TRUE(rgbtest::same_mesh(by_script, by_request));
        // Refine only adds, coarsen only removes, set may do both.
        if (kind == rgb::RequestKind::Refine) {
            EXPECT_GT(by_script.num_faces(), base.num_faces());
        } else if (kind == rgb::RequestKind::Coarsen) {
            EXPECT_LT(by_script.num_faces(), base.num_faces());
        }
    }
    EXPECT_EQ(format_detail_line({DetailCriterion::Tolerance, {0.5, true}, rgb::RequestKind::Set, std::nullopt}), "tolerance 0.5%");
    write("bad.txt", "max-edge 1 sphere 0 0 0 1 thicken\n");
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("bad.txt"), "-o", path("out.obj")}), 2);
    EXPECT_NE(::testing::internal::GetCapturedStderr().find("bad.txt:1: "), std::string::npos);
}

TEST_F(CliDetail, BadValuesAreRefused) {
    const std::string in = path("octahedron.obj"), out = path("out.obj");
    for (const char* amount : {"0", "-1", "x", "1%%", "nan", "inf", ""})
        for (const char* option : {"--max-edge", "--tolerance"}) EXPECT_EQ(run({"refine", in, "-o", out, option, amount}), 1) << option << " " << amount;
    EXPECT_EQ(run({"refine", in, "-o", out}), 1);
    EXPECT_EQ(run({"refine", in, "-o", out, "--max-edge", "1", "--tolerance", "1"}), 1);
    EXPECT_EQ(run({"refine", in, "-o", out, "--level", "2", "--tolerance", "1"}), 1);
    // A tolerance needing more triangles than allowed: refused, nothing saved.
    EXPECT_EQ(run({"refine", in, "-o", out, "--tolerance", "0.0001%", "--max-triangles", "1000"}), 3);
    for (const std::string line : {"max-edge 0", "max-edge", "tolerance -2%", "tolerance 1 sphere 0 0 0", "max-edge 1 sphere 0 0 0 0",
                                   "max-edge 1 ball 0 0 0 1", "tolerance 1e999"}) {
        write("bad.txt", "level 1\n" + line + "\n");
        ::testing::internal::CaptureStderr();
        EXPECT_EQ(run({"apply", in, path("bad.txt"), "-o", out}), 2) << line;
        const std::string err = ::testing::internal::GetCapturedStderr();
        EXPECT_NE(err.find("bad.txt:2: "), std::string::npos) << line << ": " << err;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rgbio
