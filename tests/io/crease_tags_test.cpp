// Crease and corner tags in files (issue 13): OpenSubdiv's OBJ tag lines read with errors naming
// their line, written for the saved mesh's own edges, and the base mesh's tags kept exactly by the
// saved state (format version 3, written only for tagged meshes).
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/values/restore_state.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

// In kOctahedron (0-based): 0 (1,0,0), 1 (-1,0,0), 2 (0,1,0), 3 (0,-1,0), 4 (0,0,1), 5 (0,0,-1).
// 0-2 and 2-4 are edges; 0-1 is not.
LoadedMesh with_tags(const std::string& tags) { return read_obj_text(test::kOctahedron + tags, "test.obj"); }

std::size_t count_lines(const std::string& text, const std::string& prefix) {
    std::size_t n = 0;
    for (std::size_t at = 0; (at = text.find("\n" + prefix, at)) != std::string::npos; ++at) ++n;
    return n;
}

TEST(CreaseTags, OpenSubdivTagLinesAreRead) {
    const LoadedMesh loaded = with_tags(
        "t crease 2/1/0 0 2 10\n"
        "t crease 4/2/0 2 4 4 0 1 3\n"
        "t corner 2/1/0 5 3 2.0\n"
        "t interpolateboundary 1/0/0 1\n");
    const std::vector<rgb::EdgeSharpness> edges{{0, 2, 10}, {2, 4, 1}, {4, 0, 3}};
    const std::vector<rgb::VertexSharpness> corners{{5, 2}, {3, 2}};
    EXPECT_EQ(loaded.sharp_features.edges, edges);
    EXPECT_EQ(loaded.sharp_features.corners, corners);
    EXPECT_EQ(loaded.sharp_features.boundary, rgb::BoundaryInterpolation::EdgeAndCorner);
    const rgb::Mesh mesh = build_mesh(loaded);
    EXPECT_TRUE(mesh.base().has_sharp_features());
    EXPECT_EQ(mesh.base().sharp_features().edges.size(), 3u);
}

TEST(CreaseTags, SharpnessAboveTenIsInfiniteAndOtherTagsAreSkippedWithAWarning) {
    const LoadedMesh loaded = with_tags("t crease 2/1/0 0 2 12.5\nt hole 1/0/0 3\nt smoothtriangles 1/0/0 1\n");
    EXPECT_EQ(loaded.sharp_features.edges, (std::vector<rgb::EdgeSharpness>{{0, 2, 10}}));
    EXPECT_TRUE(test::has_warning(loaded.warnings, "ignored 2 tag lines (t) rgbsub does not use (the first on line 16"));
}

TEST(CreaseTags, TagsFollowTheVerticesWhenTheLoaderRenumbersThem) {
    // An unused first vertex is dropped, so file vertices 1 and 3 become mesh vertices 0 and 2.
    const LoadedMesh loaded = read_obj_text("v 9 9 9\n" + test::kOctahedron.substr(0, test::kOctahedron.find('f')) +
                                                "f 2 4 6\nf 4 3 6\nf 3 5 6\nf 5 2 6\nf 4 2 7\nf 3 4 7\nf 5 3 7\nf 2 5 7\n"
                                                "t crease 2/1/0 1 3 10\nt corner 1/1/0 6 10\n",
                                            "test.obj");
    EXPECT_EQ(loaded.sharp_features.edges, (std::vector<rgb::EdgeSharpness>{{0, 2, 10}}));
    EXPECT_EQ(loaded.sharp_features.corners, (std::vector<rgb::VertexSharpness>{{5, 10}}));
}

TEST(CreaseTags, MalformedTagLinesAreErrorsNamingTheLine) {
    const struct {
        std::string line;
        std::string reason;
    } cases[] = {
        {"t crease 2/1/0 0 2 2.5", "fractional sharpness 2.5"},
        {"t crease 2/1/0 0 2 -1", "sharpness must be a number from 0 to 10"},
        {"t crease 2/1/0 0 1 10", "the crease 0-1 is not an edge of the mesh"},
        {"t crease 2/1/0 0 9 10", "vertex index 9 is out of range"},
        {"t corner 1/1/0 -1 10", "vertex index -1 is out of range"},
        {"t crease 2/1/0 0 2", "announces 3 values, the line has 2"},
        // Counts whose sum wraps around to the number of values on the line.
        {"t crease 18446744073709551614/1/3 0 1", "announces more than 2 values, the line has 2"},
        {"t corner 18446744073709551615/1/2 0 1", "announces more than 2 values, the line has 2"},
        {"t crease 2-1-0 0 2 10", "expected the value counts INTS/FLOATS/STRINGS"},
        {"t crease 3/1/0 0 2 4 10", "a crease needs pairs of vertex indices"},
        {"t corner 2/3/0 1 2 10 10 10", "expected one sharpness, or one per vertex (2)"},
        {"t crease 2/1/0 0 x 10", "expected a vertex index"},
        {"t crease 2/1/0 0 2 sharp", "expected a sharpness"},
        {"t interpolateboundary 1/0/0 0", "is not supported"},
        {"t interpolateboundary 1/0/0 7", "1 (edge-and-corner) or 2 (edge-only)"},
        {"t", "no tag name"},
    };
    for (const auto& c : cases) {
        const ObjError e = test::load_error(test::kOctahedron + "# a comment\n" + c.line + "\n");
        EXPECT_EQ(e.problem(), ObjProblem::BadTag) << c.line;
        EXPECT_EQ(e.line(), 16u) << c.line;
        EXPECT_NE(e.reason().find(c.reason), std::string::npos) << c.line << " gave: " << e.what();
        EXPECT_EQ(std::string(e.what()).rfind("test.obj:16: ", 0), 0u) << e.what();
    }
}

rgb::Mesh tagged_octahedron(const std::string& tags) { return build_mesh(with_tags(tags)); }

TEST(CreaseTags, SavedStateKeepsTheTagsAndRestoresTheSameMesh) {
    rgb::Mesh mesh = tagged_octahedron("t crease 2/1/0 0 2 10\nt crease 2/1/0 2 4 2\nt corner 1/1/0 5 1\n");
    rgbtest::set_level(mesh, 3, rgb::Sphere{{0.7, 0.7, 0.0}, 0.5});
    const std::string text = format_obj(mesh, {});
    EXPECT_NE(text.find("#rgb state 4\n"), std::string::npos);
    EXPECT_NE(text.find("#rgb crease 0 2 10 2 4 2\n#rgb corner 5 1\n#rgb end\n"), std::string::npos);
    const LoadedMesh back = read_obj_text(text, "saved.obj");
    ASSERT_TRUE(back.adaptive);
    EXPECT_EQ(back.adaptive->base().sharp_features(), mesh.base().sharp_features());
    EXPECT_TRUE(rgbtest::same_mesh(*back.adaptive, mesh));
}

TEST(CreaseTags, UntaggedFilesStayVersionThreeWithoutTagLines) {
    rgb::Mesh mesh = tagged_octahedron("");
    rgb::refine_uniform(mesh, 1);
    const std::string text = format_obj(mesh, {});
    EXPECT_NE(text.find("#rgb state 3\n"), std::string::npos);
    EXPECT_EQ(count_lines(text, "t "), 0u);
}

TEST(CreaseTags, TheBodysTagLinesDescribeItsOwnEdgesAtTheirLevel) {
    // Level 2: the infinite crease 0-2 is four edges of sharpness 10, the sharpness-3 crease 2-4 four
    // edges of sharpness 1; the corner of sharpness 1 at 5 has run out.
    rgb::Mesh mesh = tagged_octahedron("t crease 2/1/0 0 2 10\nt crease 2/1/0 2 4 3\nt corner 1/1/0 5 1\nt corner 1/1/0 3 10\n");
    rgb::refine_uniform(mesh, 2);
    const std::string text = format_obj(mesh, {.state = false});
    EXPECT_EQ(count_lines(text, "t crease 2/1/0 "), 8u);
    std::size_t infinite = 0, one = 0;
    for (std::size_t at = 0; (at = text.find("\nt crease", at)) != std::string::npos; ++at) {
        const std::string line = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
        infinite += line.ends_with(" 10");
        one += line.ends_with(" 1");
    }
    EXPECT_EQ(infinite, 4u);
    EXPECT_EQ(one, 4u);
    EXPECT_EQ(count_lines(text, "t corner 1/1/0 3 10"), 1u) << "base vertices come first, in base order";
    EXPECT_EQ(count_lines(text, "t corner"), 1u);

    // At level 0 the body is the base mesh, and its tag lines give back the tags.
    const rgb::Mesh base = tagged_octahedron("t crease 2/1/0 2 0 10\nt crease 2/1/0 2 4 3\nt corner 1/1/0 5 1\n");
    const LoadedMesh plain = read_obj_text(format_obj(base, {.state = false}), "plain.obj");
    EXPECT_EQ(plain.sharp_features, base.base().sharp_features());
}

TEST(CreaseTags, NewTagsKeepTheVertexSetAndMoveThePositions) {
    rgb::Mesh mesh = tagged_octahedron("");
    rgbtest::set_level(mesh, 2, rgb::Sphere{{1.0, 0.0, 0.0}, 0.8});
    rgb::SharpFeatures features;
    features.edges = {{0, 2, rgb::kInfiniteSharpness}};
    const rgb::Mesh tagged = rgb::with_sharp_features(mesh, features);
    EXPECT_EQ(tagged.num_vertices(), mesh.num_vertices());
    EXPECT_EQ(tagged.num_faces(), mesh.num_faces());
    EXPECT_FALSE(rgbtest::same_mesh(tagged, mesh)) << "the crease moves the vertices near it";
    // Refining the tagged mesh from scratch gives the same mesh.
    rgb::Mesh direct = tagged_octahedron("t crease 2/1/0 0 2 10\n");
    rgbtest::set_level(direct, 2, rgb::Sphere{{1.0, 0.0, 0.0}, 0.8});
    EXPECT_TRUE(rgbtest::same_mesh(tagged, direct));
}

}  // namespace
}  // namespace rgbio
