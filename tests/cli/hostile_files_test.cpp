// Hostile and edited files through the real executable (issue 30): a crafted tag line is bad input
// (exit 2) rather than a crash; a saved file with crease tags that another program edited works in
// every command that reads it, small or above the sizes at which files are mapped and parsed in
// blocks; an oversized material library is a warning; an output's extension counts in any case
// (OUT.GLB is binary glTF); a dab's view direction too short for a double is refused like zero.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "io/base_attributes.h"
#include "io/obj_reader.h"
#include "io/script/lod_script.h"
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

// Another program's "#rgb" comment in a complete --plain file, after "#rgb end" or before
// "#rgb state" is ignored with a warning, and the state stays (issue 30 item 7). Before, the first
// two were called truncated and the third lost the state.
TEST_F(HostileFiles, ForeignHashRgbLinesAreIgnoredWhereverTheyStand) {
    const std::string in = write_file("octahedron.obj", rgbio::test::kOctahedron);
    ASSERT_EQ(run_rgbsub({"refine", in, "-o", path("saved.obj"), "--level", "1"}).exit_code, cli::exit_ok);
    ASSERT_EQ(run_rgbsub({"refine", in, "-o", path("plain.obj"), "--level", "1", "--plain"}).exit_code, cli::exit_ok);
    const std::string saved = read(path("saved.obj")), plain = read(path("plain.obj"));
    const std::size_t state = saved.find("#rgb state");
    ASSERT_NE(state, std::string::npos);
    const std::string foreign = "#rgb hello from another program\n";
    for (const auto& [text, adaptive] : {std::pair{plain + foreign, false}, std::pair{foreign + plain, false},
                                         std::pair{saved + foreign, true}, std::pair{std::string(saved).insert(state, foreign), true}}) {
        const rgbio::LoadedMesh loaded = rgbio::read_obj_text(text, "edited.obj");
        EXPECT_EQ(loaded.adaptive != nullptr, adaptive);
        EXPECT_EQ(loaded.adaptive ? loaded.adaptive->num_faces() : loaded.triangles.size(), 32u);
        ASSERT_EQ(loaded.warnings.size(), 1u);
        EXPECT_NE(loaded.warnings[0].find("ignored 1 comment lines starting with #rgb"), std::string::npos) << loaded.warnings[0];
    }
}

// glTF export is always valid glTF (issue 30 item 9): a material name that is not UTF-8 is written
// with \xNN for its other bytes, a diffuse colour outside 0..1 is clamped, and a vertex without a
// normal (only degenerate faces around it) gets +z, each with a warning. Before, the name failed
// after the work with the JSON library's message, and the colour and the zero normals were written.
TEST_F(HostileFiles, GltfExportIsValidWhateverTheMaterialsAndFacesSay) {
    write("odd.mtl", "newmtl M\xff\nKd 2 -1 0.5\n");
    const std::string in = write_file("flat.obj", "mtllib odd.mtl\nusemtl M\xff\nv 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    const Outcome json = run_rgbsub({"refine", in, "-o", path("out.gltf"), "--level", "0"});
    ASSERT_EQ(json.exit_code, cli::exit_ok) << json.output;
    EXPECT_NE(json.output.find("1 material names are not UTF-8"), std::string::npos) << json.output;
    EXPECT_NE(json.output.find("1 materials have a diffuse colour (Kd) outside 0..1"), std::string::npos) << json.output;
    EXPECT_NE(json.output.find("3 vertices have no normal"), std::string::npos) << json.output;
    const std::string text = read(path("out.gltf"));
    EXPECT_NE(text.find("\"name\": \"M\\\\xff\""), std::string::npos) << text.substr(0, 2000);
    std::string compact = text;
    std::erase_if(compact, [](char c) { return c == ' ' || c == '\n'; });
    EXPECT_NE(compact.find("\"baseColorFactor\":[1.0,0.0,0.5,1.0]"), std::string::npos) << compact.substr(0, 2000);

    // The binary container: the three normals follow the three positions (12 bytes each) in the
    // buffer, which follows the 12-byte header, the JSON chunk and the BIN chunk's 8-byte header.
    ASSERT_EQ(run_rgbsub({"refine", in, "-o", path("out.glb"), "--level", "0"}).exit_code, cli::exit_ok);
    const std::string glb = read(path("out.glb"));
    ASSERT_GT(glb.size(), 20u);
    std::uint32_t json_length = 0;
    std::memcpy(&json_length, glb.data() + 12, 4);
    const std::size_t normals = 12 + 8 + json_length + 8 + 36;
    ASSERT_GE(glb.size(), normals + 36);
    for (int v = 0; v < 3; ++v) {
        float n[3];
        std::memcpy(n, glb.data() + normals + 12 * v, 12);
        EXPECT_EQ(n[0], 0.0f);
        EXPECT_EQ(n[1], 0.0f);
        EXPECT_EQ(n[2], 1.0f) << "vertex " << v;
    }
}

// The material names and colours glTF cannot hold are found before the work (issue 30 item 9): a
// request refused as too large (exit 3, nothing written) has already said so, in refine, apply and
// lods. Before, only the save after the work looked at them (and lods never did).
TEST_F(HostileFiles, GltfMaterialsAreCheckedBeforeTheWork) {
    write("odd.mtl", "newmtl M\xff\nKd 2 0 0\n");
    const std::string in = write_file("odd.obj", "mtllib odd.mtl\nusemtl M\xff\n" + rgbio::test::kOctahedron);
    const std::string script = write_file("fine.txt", "level 12\n");
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"refine", in, "-o", path("out.glb"), "--level", "12", "--max-triangles", "1000"},
          std::vector<std::string>{"apply", in, script, "-o", path("out.gltf"), "--max-triangles", "1000"},
          std::vector<std::string>{"lods", in, "-o", path("out.glb"), "--levels", "12,0", "--max-triangles", "1000"}}) {
        const Outcome run = run_rgbsub(command);
        EXPECT_EQ(run.exit_code, cli::exit_io_failure) << command[0] << ": " << run.output;
        EXPECT_NE(run.output.find("1 material names are not UTF-8"), std::string::npos) << command[0] << ": " << run.output;
        EXPECT_NE(run.output.find("1 materials have a diffuse colour (Kd) outside 0..1"), std::string::npos) << command[0] << ": " << run.output;
        EXPECT_FALSE(std::filesystem::exists(*std::next(std::find(command.begin(), command.end(), "-o")))) << command[0];
    }
}

// A folder name with a line break or another control byte cannot reach an mtllib line (issue 30
// item 10): the library's path is written where it has none, else the save is refused (exit 3, no
// file). Before, "mtllib ../in<LF>side/lib.mtl" injected a line.
TEST_F(HostileFiles, ControlBytesInFolderNamesNeverReachAnMtllibLine) {
    for (const std::string control : {"\n", "\r", "\f", "\v"}) {
        const std::filesystem::path folder = std::filesystem::path(path("in" + control + "side"));
        std::filesystem::create_directories(folder);
        std::ofstream(folder / "lib.mtl") << "newmtl Red\nKd 1 0 0\n";
        std::ofstream(folder / "model.obj") << "mtllib lib.mtl\nusemtl Red\n" << rgbio::test::kOctahedron;
        const std::string out = path("out.obj");
        const Outcome run = run_rgbsub({"refine", (folder / "model.obj").string(), "-o", out, "--level", "1"});
        EXPECT_EQ(run.exit_code, cli::exit_io_failure) << run.output;
        EXPECT_NE(run.output.find("holds a line break or another control character"), std::string::npos) << run.output;
        EXPECT_FALSE(std::filesystem::exists(out));
        // Saved in its own folder the reference stays as written.
        const Outcome beside = run_rgbsub({"refine", (folder / "model.obj").string(), "-o", (folder / "out.obj").string(), "--level", "1"});
        EXPECT_EQ(beside.exit_code, cli::exit_ok) << beside.output;
        EXPECT_NE(read(folder / "out.obj").find("\nmtllib lib.mtl\n"), std::string::npos);
    }
}

// Saved through a symbolic link into another folder, the mtllib and texture paths lead from the real
// file's folder (issue 30 item 11); before, from the link's.
TEST_F(HostileFiles, SavingThroughALinkWritesPathsFromTheRealFilesFolder) {
    namespace fs = std::filesystem;
    fs::create_directories(path("a"));
    fs::create_directories(path("b/real"));
    fs::create_directories(path("c"));
    write("a/lib.mtl", "newmtl Red\nKd 1 0 0\nmap_Kd tex.png\n");
    write("a/tex.png", "");
    const std::string in = write_file("a/model.obj", "mtllib lib.mtl\nusemtl Red\n" + rgbio::test::kOctahedron);
    for (const std::string name : {"out.obj", "out.gltf"}) {
        fs::create_symlink("../b/real/" + name, path("c/" + name));
        const Outcome run = run_rgbsub({"refine", in, "-o", path("c/" + name), "--level", "0"});
        ASSERT_EQ(run.exit_code, cli::exit_ok) << run.output;
        const std::string text = read(path("b/real/" + name));
        const std::string expected = name == "out.obj" ? "\nmtllib ../../a/lib.mtl\n" : "\"uri\": \"../../a/tex.png\"";
        EXPECT_NE(text.find(expected), std::string::npos) << name << ":\n" << text.substr(0, 1500);
    }
}

// A valid mesh at a scale where the numbers cannot keep its shape is refused with the reason
// (issue 30 item 14): 1e-200 across, its squared lengths underflow doubles; 1e-100 across, the
// core works (refine to OBJ) but 32-bit floats (glTF, render) would make it zeros. Before, every
// command succeeded: a blank image, a glTF of zeros.
TEST_F(HostileFiles, AMeshTooSmallForItsNumbersIsRefusedWithTheReason) {
    for (const std::string scale : {"1e-200", "1e-100"}) {
        const std::string z = "0 ", s = scale + " ";
        const std::string in = write_file("tiny.obj", "v " + s + z + z + "\nv -" + s + z + z + "\nv " + z + s + z + "\nv " + z + "-" + s + z +
                                                          "\nv " + z + z + s + "\nv " + z + z + "-" + s + "\n" +
                                                          rgbio::test::kOctahedron.substr(rgbio::test::kOctahedron.find("f ")));
        const bool doubles_hold = scale == "1e-100";
        const Outcome obj = run_rgbsub({"refine", in, "-o", path("out.obj"), "--level", "1"});
        EXPECT_EQ(obj.exit_code, doubles_hold ? cli::exit_ok : cli::exit_bad_input) << obj.output;
        if (!doubles_hold) {
            EXPECT_NE(obj.output.find("less than the 1e-150 that doubles"), std::string::npos) << obj.output;
        }
        for (const std::vector<std::string>& command : {std::vector<std::string>{"refine", in, "-o", path("out.glb"), "--level", "1"},
                                                        std::vector<std::string>{"render", in, "-o", path("out.png"), "--size", "32x24"}}) {
            const Outcome run = run_rgbsub(command);
            EXPECT_EQ(run.exit_code, cli::exit_bad_input) << run.output;
            // render checks the floats it draws with; refine the doubles it works in first.
            EXPECT_NE(run.output.find(doubles_hold || command[0] == "render" ? "32-bit floats" : "doubles"), std::string::npos) << run.output;
        }
        EXPECT_FALSE(std::filesystem::exists(path("out.glb")));
        EXPECT_FALSE(std::filesystem::exists(path("out.png")));
    }
}

// Issue 30, low items. A script's or a state line's words reach a message quoted with \xNN for
// control bytes and cut at 40 bytes; before, raw escape sequences reached the terminal.
TEST_F(HostileFiles, ControlBytesOfScriptsAndStateLinesAreQuotedInMessages) {
    const std::string escape = "\x1b[31mred";
    for (const std::string& line : {escape + "\n", "brush " + escape + " 2 0.5\n", "brush set 2 0.5\ndab 0 0 0 mirror " + escape + "\n",
                                    std::string(100, 'w') + "\n"}) {
        try {
            rgbio::parse_lod_script(line, "s.txt");
            ADD_FAILURE() << "no error for " << line;
        } catch (const rgbio::ObjError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
            EXPECT_EQ(message.find(std::string(41, 'w')), std::string::npos) << message;
            std::string shown = "'\\x1b[31mred'";
            if (line[0] == 'w') shown.assign(40, 'w').append("...'").insert(0, 1, '\'');
            EXPECT_NE(message.find(shown), std::string::npos) << message;
        }
    }
    const std::string in = write_file("octahedron.obj", rgbio::test::kOctahedron);
    ASSERT_EQ(run_rgbsub({"refine", in, "-o", path("saved.obj"), "--level", "1"}).exit_code, cli::exit_ok);
    std::string saved = read(path("saved.obj"));
    saved.insert(saved.find("#rgb end"), "#rgb " + escape + "\n");
    const Outcome run = run_rgbsub({"info", write_file("forged.obj", saved)});
    EXPECT_EQ(run.exit_code, cli::exit_bad_input) << run.output;
    EXPECT_NE(run.output.find("unknown record '\\x1b[31mred'"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find('\x1b'), std::string::npos) << run.output;
}

// Scripts' lines end at a lone CR as OBJ lines do; before, "level 1<CR>level 2<CR>" was one bad line.
TEST_F(HostileFiles, ScriptLinesEndAtALoneCarriageReturn) {
    const std::vector<rgbio::ScriptLine> script = rgbio::parse_lod_script("level 1\rrefine 2\r\ncoarsen 1\r", "s.txt");
    ASSERT_EQ(script.size(), 3u);
    EXPECT_EQ(script[1].line, 2u);
    EXPECT_EQ(script[2].text, "coarsen 1");
}

// Many libraries that cannot be read are one warning with their count; before, one warning each.
TEST_F(HostileFiles, UnreadableMaterialLibrariesAreOneWarning) {
    std::string obj;
    for (int i = 0; i < 50; ++i) obj += "mtllib missing" + std::to_string(i) + ".mtl\n";
    std::vector<std::string> warnings;
    rgbio::load_asset(write_file("many.obj", obj + rgbio::test::kOctahedron), &warnings);
    ASSERT_EQ(warnings.size(), 1u) << warnings[0];
    EXPECT_NE(warnings[0].find("50 material libraries were not read, the first '" + path("missing0.mtl") + "' (cannot read the file"),
              std::string::npos)
        << warnings[0];
}

// The output is checked before the work: a folder that is not there, or a folder as the output, is
// refused at once; before, only after the work (here: a request refused as too large first).
TEST_F(HostileFiles, TheOutputIsCheckedBeforeTheWork) {
    const std::string in = write_file("octahedron.obj", rgbio::test::kOctahedron);
    std::filesystem::create_directories(path("folder"));
    // lods writes OUT_LOD0.obj, ... (one OUT.glb for glTF); it was not checked first before.
    std::filesystem::create_directories(path("lods_LOD0.obj"));
    for (const auto& [command, refused] :
         {std::pair{std::vector<std::string>{"refine", in, "-o", path("missing/out.obj"), "--level", "20"}, path("missing/out.obj")},
          std::pair{std::vector<std::string>{"refine", in, "-o", path("folder"), "--level", "20"}, path("folder")},
          std::pair{std::vector<std::string>{"lods", in, "-o", path("missing/out.glb"), "--levels", "20,0"}, path("missing/out.glb")},
          std::pair{std::vector<std::string>{"lods", in, "-o", path("lods.obj"), "--levels", "20,0"}, path("lods_LOD0.obj")}}) {
        const Outcome run = run_rgbsub(command);
        EXPECT_EQ(run.exit_code, cli::exit_io_failure) << command[0] << ": " << run.output;
        EXPECT_NE(run.output.find("cannot save " + refused), std::string::npos) << command[0] << ": " << run.output;
        EXPECT_EQ(run.output.find("would make about"), std::string::npos) << command[0] << ": " << run.output;
    }
}

// A set of OBJ files whose finest level cannot be written leaves none of its files: the coarser
// levels are written first, LOD0 while the error is measured, and a file-size limit of 8 KiB lets the
// small ones through but not LOD0 (22 KiB).
TEST_F(HostileFiles, ASetWhoseFinestLevelCannotBeWrittenLeavesNoFile) {
    const std::string in = write_file("octahedron.obj", rgbio::test::kOctahedron);
    const Outcome run = run_rgbsub({"lods", in, "-o", path("lv.obj"), "--levels", "3,1,0"}, "ulimit -f 16;");
    EXPECT_EQ(run.exit_code, cli::exit_io_failure) << run.output;
    EXPECT_NE(run.output.find("cannot save " + path("lv_LOD0.obj")), std::string::npos) << run.output;
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(path("")))
        if (entry.path().filename() != "octahedron.obj") left.push_back(entry.path().filename().string());
    EXPECT_TRUE(left.empty()) << left.size() << " files left, the first " << left.front();
}

// A state that says format 2 but uses the -as- records of format 3 is bad input; before, it was
// restored without complaint.
TEST_F(HostileFiles, AFormatTwoStateWithFormatThreeRecordsIsRefused) {
    const std::string in = write_file("octahedron.obj", rgbio::test::kOctahedron);
    ASSERT_EQ(run_rgbsub({"refine", in, "-o", path("saved.obj"), "--level", "1", "--sphere", "1,0,0,0.1"}).exit_code, cli::exit_ok);
    std::string saved = read(path("saved.obj"));
    ASSERT_NE(saved.find("\n#rgb p-as-v "), std::string::npos);
    const std::size_t header = saved.find("#rgb state 3\n");
    ASSERT_NE(header, std::string::npos);
    saved[header + 11] = '2';
    const Outcome run = run_rgbsub({"info", write_file("old.obj", saved)});
    EXPECT_EQ(run.exit_code, cli::exit_bad_input) << run.output;
    EXPECT_NE(run.output.find("is a record of format 3 on, and the state says format 2"), std::string::npos) << run.output;
}

}  // namespace
