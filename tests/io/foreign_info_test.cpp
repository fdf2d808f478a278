// `info` prints the same report for a PLY file as for OBJ, and a bad glTF file is exit code 2 with the
// file named (the readers themselves: foreign_formats_test.cpp).
#include <gtest/gtest.h>

#include "cli/dispatch.h"
#include "foreign_fixtures.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

class ForeignInfo : public test::ScratchFolder {};

TEST_F(ForeignInfo, SameReportAsForObj) {
    const std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    write("tetra.ply", test::binary_tetrahedron_ply(false, false, p));
    testing::internal::CaptureStdout();
    const int code = cli::dispatch(std::vector<std::string>{"info", path("tetra.ply")});
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(code, 0);
    EXPECT_NE(out.find("faces: 4\n"), std::string::npos) << out;
    EXPECT_NE(out.find("Euler characteristic: 2\n"), std::string::npos) << out;
    write("bad.glb", "glTF but not really");
    testing::internal::CaptureStderr();
    EXPECT_EQ(cli::dispatch(std::vector<std::string>{"info", path("bad.glb")}), 2);
    EXPECT_NE(testing::internal::GetCapturedStderr().find(path("bad.glb")), std::string::npos);
}

}  // namespace
}  // namespace rgbio
