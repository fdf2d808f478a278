// Messages name the real cause (issue 11, item 12): truncated rgbsub files, CR-only line endings,
// unknown keywords, underflowing numbers, escape bytes, huge non-manifold edges, tangled polygons.
#include <cmath>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/repair/polygon_triangulation.h"
#include "obj_test_support.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"

namespace rgbio {
namespace {

using test::has_warning;
using test::load_error;

// A saved adaptive octahedron: header, v and f lines, then the #rgb state.
std::string saved_file() {
    rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj"));
    rgb::LevelRequest request;
    request.level = 2;
    request.sphere = rgb::Sphere{{1, 0, 0}, 0.5};
    rgb::apply_request(mesh, request);
    return format_obj(mesh, {});
}

TEST(ObjLoadMessages, EveryCutOfASavedFileSaysItIsTruncated) {
    const std::string text = saved_file();
    ASSERT_TRUE(read_obj_text(text, "saved.obj").adaptive);
    const std::size_t header_end = text.find('\n') + 1;
    // Every cut after the header line, through v, f and #rgb lines, except dropping only the
    // final newline (then nothing is missing).
    for (std::size_t cut = header_end; cut + 1 < text.size(); ++cut) {
        const ObjError e = load_error(text.substr(0, cut));
        ASSERT_EQ(e.problem(), ObjProblem::Truncated) << "cut at byte " << cut << ": " << e.what();
        ASSERT_NE(e.reason().find("the file is truncated"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(read_obj_text(text.substr(0, text.size() - 1), "saved.obj").adaptive);
}

TEST(ObjLoadMessages, TruncationNamesWhatTheHeaderPromised) {
    const std::string text = saved_file();
    const std::size_t faces = text.find("\nf ");
    const ObjError e = load_error(text.substr(0, faces + 1));  // all v lines, no f line
    EXPECT_EQ(e.problem(), ObjProblem::Truncated);
    const std::string header = text.substr(0, text.find('\n'));
    const std::size_t vertices = std::stoul(header.substr(header.find(": ") + 2));
    const std::size_t triangles = std::stoul(header.substr(header.find(", ") + 2));
    EXPECT_NE(e.reason().find("announces " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                              " triangles, and it holds " + std::to_string(vertices) + " vertices and 0 faces"),
              std::string::npos)
        << e.what();
}

TEST(ObjLoadMessages, CarriageReturnOnlyLineEndingsWork) {
    std::string text = test::kOctahedron;
    for (char& c : text)
        if (c == '\n') c = '\r';
    const LoadedMesh mesh = read_obj_text(text, "mac.obj");
    const LoadedMesh reference = read_obj_text(test::kOctahedron, "unix.obj");
    EXPECT_EQ(mesh.positions, reference.positions);
    EXPECT_EQ(mesh.triangles, reference.triangles);
    // Line numbers count the CRs.
    const ObjError e = load_error("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 4\r");
    EXPECT_EQ(e.line(), 4u);
}

TEST(ObjLoadMessages, UnknownKeywordsAreReportedAndExplainIndexErrors) {
    const ObjError e = load_error("V 0 0 0\nV 1 0 0\nV 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(e.problem(), ObjProblem::FaceIndexOutOfRange);
    EXPECT_NE(e.reason().find("face index 1 is out of range (0 vertices defined before this line); note: 3 lines with an "
                              "unknown keyword were ignored before, the first on line 1 ('V'; OBJ keywords are lower case)"),
              std::string::npos)
        << e.what();
    const LoadedMesh mesh = read_obj_text("Vx 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\ncurv 0 1 1 2\nf 1 2 3\n", "odd.obj");
    EXPECT_EQ(mesh.warnings, (std::vector<std::string>{
                                 "ignored 1 OBJ statements rgbsub does not use (free-form geometry, display attributes; the first "
                                 "on line 5: 'curv')",
                                 "ignored 1 lines with an unknown keyword (the first on line 1: 'Vx'; OBJ keywords are lower case)"}));
}

TEST(ObjLoadMessages, NumbersTooSmallForADoubleAreZeroNotOutOfRange) {
    const LoadedMesh mesh = read_obj_text("v 1e-400 -1e-400 0.000e-99999999999999999999\nv 1 0 4.9e-324\nv 0 1 0\nf 1 2 3\n", "tiny.obj");
    EXPECT_EQ(mesh.positions[0], glm::dvec3(0, 0, 0));
    EXPECT_TRUE(std::signbit(mesh.positions[0].y));
    EXPECT_EQ(mesh.positions[1].z, 4.9406564584124654e-324);  // the smallest subnormal, exactly
    const ObjError huge = load_error("v 1e400 0 0\n");
    EXPECT_EQ(huge.problem(), ObjProblem::AbsurdCoordinate);
    EXPECT_NE(huge.reason().find("out of the range of a double"), std::string::npos);
    EXPECT_NE(load_error("v 0.0000000001e320 0 0\n").reason().find("out of the range of a double"), std::string::npos);  // 1e310
    EXPECT_EQ(read_obj_text("v 123e-400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tiny.obj").positions[0].x, 0.0);
}

TEST(ObjLoadMessages, ControlBytesFromTheFileAreEscaped) {
    const ObjError e = load_error("v 1 2 \x1b[2J\x07\n");
    EXPECT_EQ(e.reason(), "vertex coordinate '\\x1b[2J\\x07' is not a number");
    EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos);
    const LoadedMesh mesh = read_obj_text("\x1b]0;title\x07 x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "escape.obj");
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_NE(mesh.warnings[0].find("'\\x1b]0;title\\x07'"), std::string::npos) << mesh.warnings[0];
}

TEST(ObjLoadMessages, AnEdgeOfAHundredThousandFacesGivesAShortMessage) {
    std::string text = "v 0 0 0\nv 1 0 0\n";
    constexpr int kFaces = 100000;
    for (int i = 0; i < kFaces; ++i) text += "v 0 1 " + std::to_string(i) + "\n";
    for (int i = 0; i < kFaces; ++i) text += "f 1 2 " + std::to_string(i + 3) + "\n";
    const ObjError e = load_error(text, {.strict = true});
    EXPECT_EQ(e.problem(), ObjProblem::NonManifoldEdge);
    EXPECT_LT(std::string(e.what()).size(), 300u) << e.what();
    EXPECT_NE(e.reason().find("edge 1-2 has 100000 faces (lines 100003 100004 100005 100006 100007 100008 100009 100010 and 99992 more)"),
              std::string::npos)
        << e.what();
}

TEST(ObjLoadMessages, ATangledPolygonBeyondTheWorkBudgetIsRefused) {
    // Triangulation gives up past its work budget rather than hang (the default budget is linear in
    // the polygon's size; a tiny one shows the refusal on a small star).
    std::vector<glm::dvec3> star;
    std::vector<std::uint32_t> polygon;
    for (std::uint32_t i = 0; i < 40; ++i) {
        const double r = i % 2 ? 0.3 : 1.0, a = 3.141592653589793 * i / 20;
        star.push_back({r * std::cos(a), r * std::sin(a), 0});
        polygon.push_back(i);
    }
    EXPECT_TRUE(triangulate_polygon_corners(star, polygon, 10).empty());
    EXPECT_EQ(triangulate_polygon_corners(star, polygon).size(), 38u);
}

}  // namespace
}  // namespace rgbio
