// Saved files with crease tags on every path a file takes through the loader (issue 30): read into
// memory or mapped (from 4 MiB), parsed in one piece or in blocks (from 8 MiB on two cores). A
// saved file that another program edited loads as the plain mesh its lines give, with its tags and
// a warning (its tag lines are read before the text is released); a --plain file keeps every tag,
// wherever its t lines fall, and one cut just before them is known as cut.
#include <string>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "scratch_folder.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

using test::has_warning;

class TaggedSavedFiles : public test::ScratchFolder {
protected:
    // The tagged octahedron refined everywhere to `level`, saved as `name` (its path returned).
    std::string save_tagged(const std::string& name, int level, const SaveOptions& options = {}) const {
        const std::string tags = "t crease 2/1/0 0 2 10\nt crease 2/1/0 2 4 10\nt corner 1/1/0 5 10\n";
        rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron + tags, "tagged.obj"));
        rgbtest::set_level(mesh, level);
        save_mesh(mesh, path(name), options);
        return path(name);
    }
};

std::size_t count_lines_starting(const std::string& text, const std::string& start) {
    std::size_t count = 0;
    for (std::size_t at = text.find("\n" + start); at != std::string::npos; at = text.find("\n" + start, at + 1)) ++count;
    return count;
}

// The file's first v line replaced by one of the same length elsewhere, as another program may.
void move_first_vertex(std::string& text) {
    const std::size_t begin = text.find("\nv ") + 1, end = text.find('\n', begin);
    std::string moved = "v 2 0 0";
    moved.resize(end - begin, ' ');
    text.replace(begin, end - begin, moved);
}

// Levels 2 and 7: a few KB (read into memory, parsed in one piece), and with vn lines above 8 MiB
// (mapped and, with two cores or more, parsed in blocks, the t lines in a later one).
TEST_F(TaggedSavedFiles, AnEditedFileLoadsAsAPlainMeshWithItsTags) {
    SaveOptions with_normals;
    with_normals.normals = true;
    for (const int level : {2, 7}) {
        SCOPED_TRACE("level " + std::to_string(level));
        const std::string file = save_tagged("edited.obj", level, with_normals);
        std::string text = read(file);
        if (level == 7) {
            ASSERT_GE(text.size(), std::size_t(8) << 20);
        }
        move_first_vertex(text);
        write("edited.obj", text);
        const LoadedMesh loaded = read_obj_file(file);
        EXPECT_FALSE(loaded.adaptive);
        EXPECT_TRUE(has_warning(loaded.warnings, "edited by another program")) << loaded.warnings.front();
        EXPECT_EQ(loaded.sharp_features.edges.size(), count_lines_starting(text, "t crease "));
        EXPECT_EQ(loaded.sharp_features.edges.size(), 2u << level);
        EXPECT_EQ(loaded.sharp_features.corners.size(), 1u);
    }
}

// rgbsub's own --plain output (with vn lines) above 8 MiB: its t lines come last, in the last block.
TEST_F(TaggedSavedFiles, APlainFileKeepsTagsFromEveryBlock) {
    SaveOptions plain;
    plain.state = false;
    plain.normals = true;
    const std::string file = save_tagged("plain.obj", 7, plain);
    ASSERT_GE(read(file).size(), std::size_t(8) << 20);
    const LoadedMesh loaded = read_obj_file(file);
    EXPECT_EQ(loaded.sharp_features.edges.size(), 2u << 7);
    EXPECT_EQ(loaded.sharp_features.corners.size(), 1u);
}

// A --plain file has no state whose end line would show a cut: its header counts its t lines.
TEST_F(TaggedSavedFiles, APlainFileCutBeforeItsTagLinesIsTruncated) {
    SaveOptions plain;
    plain.state = false;
    const std::string text = read(save_tagged("plain.obj", 1, plain));
    const std::size_t tags = text.find("\nt ");
    ASSERT_NE(tags, std::string::npos);
    const ObjError error = test::load_error(text.substr(0, tags + 1));
    EXPECT_EQ(error.problem(), ObjProblem::Truncated);
    EXPECT_NE(error.reason().find("tag lines (t)"), std::string::npos) << error.what();
    EXPECT_EQ(read_obj_text(text, "whole.obj").sharp_features.edges.size(), 2u << 1);
}

}  // namespace
}  // namespace rgbio
