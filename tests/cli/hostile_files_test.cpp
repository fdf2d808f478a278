// Hostile and edited files through the real executable (issue 30): a crafted tag line is bad input
// (exit 2) rather than a crash; a saved file with crease tags that another program edited works in
// every command that reads it, small or above the sizes at which files are mapped and parsed in
// blocks; an oversized material library is a warning; an output's extension counts in any case
// (OUT.GLB is binary glTF); a dab's view direction too short for a double is refused like zero.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "obj_test_support.h"
#include "run_rgbsub.h"
#include "scratch_folder.h"

namespace {

using cli_test::Outcome;
using cli_test::run_rgbsub;

class HostileFiles : public rgbio::test::ScratchFolder {
protected:
    std::string write_file(const std::string& name, const std::string& text) const {
        write(name, text);
        return path(name);
    }
};

const std::string kTaggedOctahedron =
    rgbio::test::kOctahedron + "t crease 2/1/0 0 2 10\nt crease 2/1/0 2 4 10\nt corner 1/1/0 5 10\n";

TEST_F(HostileFiles, TagCountsThatWrapAroundAreBadInput) {
    for (const std::string line : {"t crease 18446744073709551614/1/3 0 1", "t corner 18446744073709551615/1/2 0 1"}) {
        const std::string file = write_file("crafted.obj", rgbio::test::kOctahedron + line + "\n");
        const Outcome run = run_rgbsub({"info", file});
        EXPECT_EQ(run.exit_code, cli::exit_bad_input) << line << ": " << run.output;
        EXPECT_NE(run.output.find(file + ":15: tag line (t): '18446744073709551"), std::string::npos) << run.output;
    }
}

// Levels 2 and 7 of the tagged octahedron: a few KB, and with vn lines above 8 MiB (mapped, parsed
// in blocks).
TEST_F(HostileFiles, AnEditedTaggedSavedFileWorksInEveryCommand) {
    const std::string tagged = write_file("tagged.obj", kTaggedOctahedron);
    const std::string script = write_file("keep.txt", "coarsen 0\n");
    for (const int level : {2, 7}) {
        SCOPED_TRACE("level " + std::to_string(level));
        const std::string saved = path("saved.obj");
        ASSERT_EQ(run_rgbsub({"refine", tagged, "-o", saved, "--level", std::to_string(level), "--normals"}).exit_code, cli::exit_ok);
        std::string text = read(saved);
        if (level == 7) {
            ASSERT_GE(text.size(), std::size_t(8) << 20);
        }
        // The first v line moved, its length kept, as another program may do.
        const std::size_t begin = text.find("\nv ") + 1, end = text.find('\n', begin);
        std::string moved = "v 2 0 0";
        moved.resize(end - begin, ' ');
        write("saved.obj", text.replace(begin, end - begin, moved));

        const Outcome info = run_rgbsub({"info", saved});
        EXPECT_EQ(info.exit_code, cli::exit_ok) << info.output;
        EXPECT_NE(info.output.find("probably edited by another program"), std::string::npos) << info.output;
        EXPECT_NE(info.output.find("sharp edges: " + std::to_string(2 << level) + " ("), std::string::npos) << info.output;
        for (const std::vector<std::string>& command :
             {std::vector<std::string>{"refine", saved, "-o", path("out.obj"), "--level", "0"},
              std::vector<std::string>{"apply", saved, script, "-o", path("out.obj")},
              std::vector<std::string>{"render", saved, "-o", path("out.png"), "--size", "32x24"}}) {
            const Outcome run = run_rgbsub(command);
            EXPECT_EQ(run.exit_code, cli::exit_ok) << command[0] << ": " << run.output;
            EXPECT_NE(run.output.find("probably edited by another program"), std::string::npos) << command[0] << ": " << run.output;
        }
    }
}

// Sparse, so it takes no disk space; removed with the folder.
TEST_F(HostileFiles, AnOversizedMaterialLibraryIsAWarning) {
    const std::string library = write_file("huge.mtl", "newmtl Huge\nKd 1 0 0\n");
    std::filesystem::resize_file(library, std::uintmax_t(64) << 20);
    const std::string file = write_file("model.obj", "mtllib huge.mtl\nusemtl Huge\n" + rgbio::test::kOctahedron);
    const Outcome run = run_rgbsub({"info", file});
    EXPECT_EQ(run.exit_code, cli::exit_ok) << run.output;
    EXPECT_NE(run.output.find("material library '" + library + "' was not read (it is 67108864 bytes"), std::string::npos)
        << run.output;
}

TEST_F(HostileFiles, OutputExtensionsCountInAnyCase) {
    const std::string tagged = write_file("tagged.obj", kTaggedOctahedron);
    for (const std::string name : {"out.GLB", "out.Glb"}) {
        const Outcome run = run_rgbsub({"refine", tagged, "-o", path(name), "--level", "1"});
        ASSERT_EQ(run.exit_code, cli::exit_ok) << run.output;
        EXPECT_EQ(read(path(name)).substr(0, 4), "glTF") << name << " is binary glTF";
    }
}

// A length that underflows (or overflows) a double is as good as no direction at all.
TEST_F(HostileFiles, AViewDirectionWithoutANormalLengthIsRefused) {
    const std::string mesh = write_file("mesh.obj", rgbio::test::kOctahedron);
    for (const std::string view : {"0 0 -1e-300", "1e-200 0 0", "1e300 1e300 0"}) {
        const std::string script = write_file("dabs.txt", "brush refine 2 0.5\ndab 1 0 0 " + view + "\n");
        const Outcome run = run_rgbsub({"apply", mesh, script, "-o", path("out.obj")});
        EXPECT_EQ(run.exit_code, cli::exit_bad_input) << view << ": " << run.output;
        EXPECT_NE(run.output.find(script + ":2: "), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("view direction"), std::string::npos) << run.output;
    }
}

}  // namespace
