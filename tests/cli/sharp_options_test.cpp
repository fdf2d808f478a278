// The crease options from the command line (issue 13): --sharp-angle tags the machined part's edges
// above the angle (its generator, assets/make_machined_part.py, states the answer: 44 edges above 30
// degrees, 40 above 60, none above 90), info reports them, refine saves them with the state, render
// draws them as coloured lines, and --boundary chooses OpenSubdiv's boundary rule.
#include <string>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "render/image.h"
#include "run_rgbsub.h"
#include "scratch_folder.h"

namespace {

using cli_test::Outcome;
using cli_test::run_rgbsub;

const std::string kPart = RGBSUB_SOURCE_DIR "/assets/machined_part.obj";

bool printed(const Outcome& run, const std::string& text) { return run.output.find(text) != std::string::npos; }

class SharpOptions : public rgbio::test::ScratchFolder {};

TEST_F(SharpOptions, SharpAngleTagsTheEdgesAboveIt) {
    const Outcome thirty = run_rgbsub({"info", kPart, "--sharp-angle", "30"});
    EXPECT_EQ(thirty.exit_code, cli::exit_ok) << thirty.output;
    EXPECT_TRUE(printed(thirty, "sharp edges: 44 (44 infinitely sharp, 0 semi-sharp)\n")) << thirty.output;
    EXPECT_TRUE(printed(thirty, "boundary interpolation: edge-only\n")) << thirty.output;
    EXPECT_TRUE(printed(run_rgbsub({"info", kPart, "--sharp-angle=60"}), "sharp edges: 40 ("));
    EXPECT_FALSE(printed(run_rgbsub({"info", kPart, "--sharp-angle", "100"}), "sharp edges"));
    EXPECT_FALSE(printed(run_rgbsub({"info", kPart}), "sharp edges")) << "no edge is sharp unless tagged";
}

TEST_F(SharpOptions, BadValuesAreUsageErrors) {
    const Outcome angle = run_rgbsub({"info", kPart, "--sharp-angle", "200"});
    EXPECT_EQ(angle.exit_code, cli::exit_usage);
    EXPECT_TRUE(printed(angle, "--sharp-angle must be between 0 and 180 degrees")) << angle.output;
    const Outcome boundary = run_rgbsub({"refine", kPart, "-o", path("out.obj"), "--level", "1", "--boundary", "none"});
    EXPECT_EQ(boundary.exit_code, cli::exit_usage);
    EXPECT_TRUE(printed(boundary, "--boundary must be 'edge-only' or 'edge-and-corner', not 'none'")) << boundary.output;
}

TEST_F(SharpOptions, RefineSavesTheTagsWithTheStateAndLaterCommandsKeepThem) {
    const Outcome refine = run_rgbsub({"refine", kPart, "-o", path("level2.obj"), "--level", "2", "--sharp-angle", "30"});
    ASSERT_EQ(refine.exit_code, cli::exit_ok) << refine.output;
    const std::string saved = read(path("level2.obj"));
    EXPECT_NE(saved.find("#rgb state 4\n"), std::string::npos);
    EXPECT_NE(saved.find("\nt crease 2/1/0 "), std::string::npos) << "the body's creases, for other programs";
    ASSERT_EQ(run_rgbsub({"refine", path("level2.obj"), "-o", path("level3.obj"), "--level", "3"}).exit_code, cli::exit_ok);
    const Outcome info = run_rgbsub({"info", path("level3.obj")});
    EXPECT_TRUE(printed(info, "adaptive state: restored")) << info.output;
    EXPECT_TRUE(printed(info, "sharp edges: 44 (44 infinitely sharp, 0 semi-sharp)")) << info.output;
}

TEST_F(SharpOptions, EdgeAndCornerMakesSingleFaceBoundaryVerticesCorners) {
    // One quad cut into two triangles: two of its corners have a single face.
    write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
    const Outcome info = run_rgbsub({"info", path("quad.obj"), "--boundary", "edge-and-corner"});
    EXPECT_TRUE(printed(info, "corners: 0 tagged, and 2 boundary vertices with a single face\n")) << info.output;
    EXPECT_TRUE(printed(info, "boundary interpolation: edge-and-corner\n")) << info.output;
    ASSERT_EQ(run_rgbsub({"refine", path("quad.obj"), "-o", path("quad3.obj"), "--level", "3", "--boundary", "edge-and-corner",
                          "--plain"})
                  .exit_code,
              cli::exit_ok);
    // The corners stay put (the first two v lines are base vertices 0 and 1; 1 has a single face).
    const std::string saved = read(path("quad3.obj"));
    EXPECT_NE(saved.find("\nv 1 0 0\n"), std::string::npos) << saved.substr(0, 300);
    EXPECT_NE(saved.find("t interpolateboundary 1/0/0 1\n"), std::string::npos);
}

// The render command's screenshot: the tagged part at level 3 shows magenta crease lines.
TEST_F(SharpOptions, RenderDrawsCreasesAsColouredLines) {
    ASSERT_EQ(run_rgbsub({"refine", kPart, "-o", path("part3.obj"), "--level", "3"}).exit_code, cli::exit_ok);
    auto magenta_pixels = [&](const std::vector<std::string>& extra) {
        std::vector<std::string> arguments{"render", path("part3.obj"), "-o", path("part.png"), "--size", "320x240"};
        arguments.insert(arguments.end(), extra.begin(), extra.end());
        const Outcome run = run_rgbsub(arguments);
        EXPECT_EQ(run.exit_code, cli::exit_ok) << run.output;
        const render::Image image = render::decode_png(read(path("part.png")));
        std::size_t n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const auto p = image.pixel(x, y);
                n += p.r > 150 && p.b > 80 && p.g + 60 < p.b;
            }
        return n;
    };
    EXPECT_EQ(magenta_pixels({}), 0u);
    EXPECT_GT(magenta_pixels({"--sharp-angle", "30"}), 200u);
}

}  // namespace
