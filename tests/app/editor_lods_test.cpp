// Export LODs in the editor: the levels previewed are those `rgbsub lods` writes, previewing leaves
// the document alone, the export writes the CLI's files (binary .msh ones when the Files panel asks for
// them, as `--msh-binary`, and Save as too), and bad values are refused in the panel.
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "cli/run_rgbsub.h"
#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "small_meshes.h"
#include "test_paths.h"

namespace app::test {
namespace {

std::string lod_file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The tetrahedron as a plain OBJ file in `folder`, opened in an editor.
class EditorLods : public ::testing::Test {
protected:
    void SetUp() override {
        folder = fresh_folder(std::string("editor_lods_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        input = (folder / "tet.obj").string();
        rgbio::SaveOptions plain;
        plain.state = false;
        rgbio::save_mesh(tetrahedron(), input, plain);
        ASSERT_TRUE(editor.open(input)) << editor.message();
    }

    // `rgbsub lods` of the input with these arguments (and `extra`, if not empty), writing to `output`.
    void run_cli(const std::string& option, const std::string& values, const std::filesystem::path& output,
                 const std::string& extra = "") {
        std::vector<std::string> args = {"lods", input, "-o", output.string(), option, values};
        if (!extra.empty()) args.push_back(extra);
        const cli_test::Outcome run = cli_test::run_rgbsub(args);
        ASSERT_EQ(run.exit_code, 0) << run.output;
    }

    std::filesystem::path folder;
    std::string input;
    Editor editor{glm::ivec2(800, 600)};
};

TEST_F(EditorLods, EachPreviewShowsTheLevelTheCliWritesAndLeavesTheDocumentAlone) {
    run_cli("--budgets", "40,10,4", folder / "cli.obj");
    editor.lod_export_settings().criterion = rgbio::LodSetCriterion::Budgets;
    editor.lod_export_settings().values = "10,40,4";  // any order, as the CLI takes them
    const std::uint64_t changes = editor.document().changes();
    const std::size_t faces = editor.document().mesh().num_faces();
    editor.start_lod_levels();
    ASSERT_NE(editor.lod_task(), nullptr) << "made in the background";
    EXPECT_TRUE(editor.needs_frames());
    editor.finish_work();
    const LodLevels* levels = editor.lod_levels();
    ASSERT_NE(levels, nullptr) << editor.lod_problem();
    ASSERT_EQ(levels->set.levels.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        editor.preview_lod(i);
        const std::optional<Editor::LodPreview> preview = editor.lod_preview();
        ASSERT_TRUE(preview.has_value());
        // The CLI's file of this level, read back: the preview shows its triangles at its positions.
        const rgbio::LoadedMesh written = rgbio::read_obj_file(rgbio::lod_file_name((folder / "cli.obj").string(), i));
        ASSERT_EQ(preview->mesh->num_faces(), written.triangles.size()) << "LOD" << i;
        std::size_t k = 0;
        for (rgb::FaceId f : preview->mesh->faces()) {
            const std::array<glm::dvec3, 3> corners = preview->display->corners(f);
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(glm::vec3(corners[c]), glm::vec3(written.positions[written.triangles[k][c]])) << "LOD" << i << " face " << k;
            ++k;
        }
    }
    editor.preview_lod(std::nullopt);
    EXPECT_FALSE(editor.lod_preview().has_value()) << "the slider's left end shows the mesh again";
    EXPECT_EQ(editor.document().changes(), changes);
    EXPECT_EQ(editor.document().mesh().num_faces(), faces);
    EXPECT_FALSE(editor.document().dirty());
    EXPECT_FALSE(editor.document().history().can_undo());
    // An edit makes the levels stale: the preview ends.
    editor.preview_lod(1);
    editor.start_flood_fill(1);
    editor.finish_work();
    EXPECT_EQ(editor.lod_levels(), nullptr);
    EXPECT_FALSE(editor.lod_preview().has_value());
}

TEST_F(EditorLods, TheExportWritesTheFilesOfTheCli) {
    std::filesystem::create_directory(folder / "cli");
    std::filesystem::create_directory(folder / "editor");
    for (const std::string name : {"lv.obj", "lv.glb", "lv.msh"}) {
        const bool msh = name == "lv.msh";
        run_cli("--levels", "2,0,1", folder / "cli" / name, msh ? "--msh-binary" : "");
        editor.save_options().msh = msh ? rgbio::MshEncoding::Binary : rgbio::MshEncoding::Ascii;
        editor.lod_export_settings().criterion = rgbio::LodSetCriterion::Levels;
        editor.lod_export_settings().values = "2,0,1";
        editor.start_lod_export((folder / "editor" / name).string());
        editor.finish_work();
        ASSERT_TRUE(editor.lod_problem().empty()) << editor.lod_problem();
        ASSERT_NE(editor.lod_levels(), nullptr) << "the levels exported are the preview's";
        const bool one_file = name == "lv.glb";
        for (std::size_t i = 0; i < (one_file ? 1 : 3); ++i) {
            const std::string file = one_file ? name : rgbio::lod_file_name(name, i);
            const std::string expected = lod_file_bytes(folder / "cli" / file);
            ASSERT_FALSE(expected.empty()) << file;
            if (msh) {
                EXPECT_EQ(expected.substr(0, 20), "$MeshFormat\n4.1 1 8\n") << file;
            }
            EXPECT_EQ(lod_file_bytes(folder / "editor" / file), expected) << file;
        }
    }
    // Save as writes the same encoding: the mesh (at level 0) at limit positions is LOD2 of the set above
    // (levels 2, 1, 0: finest first).
    editor.save_options().positions = rgbio::SavedPositions::Limit;
    editor.request_save_as((folder / "editor" / "saved.msh").string());
    editor.finish_work();
    ASSERT_FALSE(editor.message_is_error()) << editor.message();
    EXPECT_EQ(lod_file_bytes(folder / "editor" / "saved.msh"), lod_file_bytes(folder / "cli" / "lv_LOD2.msh"));
}

TEST_F(EditorLods, BadValuesAreRefusedInThePanel) {
    struct Case {
        rgbio::LodSetCriterion criterion;
        const char* values;
        const char* says;
    };
    for (const Case& bad : {Case{rgbio::LodSetCriterion::Levels, "", "levels: "}, Case{rgbio::LodSetCriterion::Budgets, "400,400", "budgets: "},
                            Case{rgbio::LodSetCriterion::Tolerances, "-0.1", "tolerances: "}, Case{rgbio::LodSetCriterion::Levels, "2,,1", "levels: "}}) {
        editor.lod_export_settings().criterion = bad.criterion;
        editor.lod_export_settings().values = bad.values;
        editor.start_lod_levels();
        EXPECT_EQ(editor.lod_task(), nullptr) << bad.values;
        EXPECT_TRUE(editor.lod_problem().starts_with(bad.says)) << bad.values << " -> " << editor.lod_problem();
    }
    editor.start_lod_export("");
    EXPECT_NE(editor.lod_problem().find("no file to export to"), std::string::npos) << editor.lod_problem();
}

TEST_F(EditorLods, EscStopsMakingTheLevels) {
    editor.start_lod_levels();
    ASSERT_NE(editor.lod_task(), nullptr);
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.lod_task(), nullptr);
    editor.finish_work();
    EXPECT_EQ(editor.lod_levels(), nullptr);
    EXPECT_EQ(editor.message(), "stopped making the LODs");
}

TEST_F(EditorLods, AFailedExportWritesNothing) {
    // LOD1's file cannot be written (a folder has its name): LOD0's, written first, goes again.
    const std::filesystem::path output = folder / "lv.obj";
    std::filesystem::create_directory(rgbio::lod_file_name(output.string(), 1));
    editor.lod_export_settings().values = "1,0";
    editor.start_lod_export(output.string());
    editor.finish_work();
    EXPECT_NE(editor.lod_problem().find("could not export the LODs"), std::string::npos) << editor.lod_problem();
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_FALSE(std::filesystem::exists(rgbio::lod_file_name(output.string(), 0)));
    EXPECT_EQ(editor.lod_levels(), nullptr);
}

}  // namespace
}  // namespace app::test
