// One table of exit codes, true for every command: each subcommand is run through each row of the
// table in docs/cli.md (ok, usage error, bad input, I/O or resource failure) and must exit with the
// code the table gives that row. The expected codes are read from docs/cli.md, not from the program.
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "obj_test_support.h"
#include "run_rgbsub.h"
#include "scratch_folder.h"

namespace {

// Rows "| 0 | ok | ..." of docs/cli.md's exit code table: meaning -> code.
std::map<std::string, int> documented_exit_codes() {
    std::ifstream readme(RGBSUB_SOURCE_DIR "/docs/cli.md");
    std::map<std::string, int> codes;
    const std::regex row(R"(^\| (\d) \| ([^|]+?) \|)");
    bool in_table = false;
    for (std::string line; std::getline(readme, line);) {
        if (line == "## Exit codes") in_table = true;
        else if (in_table && line.starts_with("#")) break;
        std::smatch match;
        if (in_table && std::regex_search(line, match, row)) codes[match[2]] = std::stoi(match[1]);
    }
    return codes;
}

struct Case {
    std::vector<std::string> args;
    std::string row;  // the table's meaning
    std::string shell_prefix = {};
};

class ExitCodes : public rgbio::test::ScratchFolder {};

TEST_F(ExitCodes, EveryCommandFollowsTheDocumentedTable) {
    const std::map<std::string, int> table = documented_exit_codes();
    ASSERT_EQ(table, (std::map<std::string, int>{{"ok", 0}, {"usage error", 1}, {"bad input", 2}, {"I/O or resource failure", 3}}))
        << "docs/cli.md's table changed: update this test's cases with it";

    write("mesh.obj", rgbio::test::kOctahedron);
    // A face naming a vertex the file does not have: no repair can make a mesh of it.
    write("broken.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n");
    write("script.txt", "level 2\n");
    write("bad_script.txt", "level 2\nbogus\n");
    ::mkdir(path("folder").c_str(), 0755);
    const std::string mesh = path("mesh.obj"), broken = path("broken.obj"), missing = path("missing.obj"), folder = path("folder");
    const std::string obj = path("out.obj"), png = path("out.png");
    const std::string tiny_disk = "ulimit -f 1;";  // a file-size limit of 512 bytes acts as a full disk

    const std::vector<Case> cases{
        {{"edit", mesh, "--screenshot", png}, "ok"},
        {{"edit", mesh, "--screenshot", png, "--mode", "texture"}, "ok"},
        {{"edit", mesh, "--screenshot", png, "--mode", "textures"}, "usage error"},
        {{"edit", "-x"}, "usage error"},
        {{"edit", mesh, "--cage-above", "-1"}, "usage error"},
        {{"edit", mesh, "--cage-above", "many"}, "usage error"},
        {{"edit", mesh, "--screenshot", png, "--screenshot", png}, "usage error"},
        {{"edit", broken, "--screenshot", png}, "bad input"},
        {{"edit", missing, "--screenshot", png}, "I/O or resource failure"},
        {{"edit", mesh, "--screenshot", folder}, "I/O or resource failure"},
        {{"edit", mesh, "--screenshot", png}, "I/O or resource failure", tiny_disk},

        {{"render", mesh, "-o", png, "--size", "64x48"}, "ok"},
        {{"render", mesh, "-o", png, "-x"}, "usage error"},
        {{"render", mesh, "-o", "-o"}, "usage error"},
        {{"render", mesh, "-o", png, "--view", "nan,0"}, "usage error"},
        {{"render", broken, "-o", png}, "bad input"},
        {{"render", missing, "-o", png}, "I/O or resource failure"},
        {{"render", mesh, "-o", folder}, "I/O or resource failure"},
        {{"render", mesh, "-o", ""}, "I/O or resource failure"},
        {{"render", mesh, "-o", png, "--size", "64x48"}, "I/O or resource failure", tiny_disk},
        {{"render", mesh, "-o", png, "--size", "64x48", "--screen-lod", "4", "--lod-view", "200,10"}, "ok"},
        {{"render", mesh, "-o", png, "--screen-lod", "0"}, "usage error"},
        {{"render", mesh, "-o", png, "--lod-view", "10,10"}, "usage error"},
        {{"render", mesh, "-o", png, "--screen-lod", "1", "--max-triangles", "20"}, "I/O or resource failure"},

        {{"info", mesh}, "ok"},
        {{"info", "-x", mesh}, "usage error"},
        {{"info", mesh, mesh}, "usage error"},
        {{"info", broken}, "bad input"},
        {{"info", missing}, "I/O or resource failure"},
        {{"info", folder}, "I/O or resource failure"},

        {{"refine", mesh, "-o", obj, "--level", "2"}, "ok"},
        {{"refine", mesh, "-o", obj, "--level", "2", "-x"}, "usage error"},
        {{"refine", mesh, "-o", obj, "-o", obj, "--level", "2"}, "usage error"},
        {{"refine", broken, "-o", obj, "--level", "2"}, "bad input"},
        {{"refine", missing, "-o", obj, "--level", "2"}, "I/O or resource failure"},
        {{"refine", mesh, "-o", folder, "--level", "2"}, "I/O or resource failure"},
        {{"refine", mesh, "-o", obj, "--level", "2"}, "I/O or resource failure", tiny_disk},
        {{"refine", mesh, "-o", obj, "--tolerance", "0.5%"}, "ok"},
        {{"refine", mesh, "-o", obj, "--max-edge", "0"}, "usage error"},
        {{"refine", mesh, "-o", obj, "--tolerance", "0.0001%", "--max-triangles", "100"}, "I/O or resource failure"},

        {{"apply", mesh, path("script.txt"), "-o", obj}, "ok"},
        {{"apply", mesh, path("script.txt"), "-o", obj, "-x"}, "usage error"},
        {{"apply", mesh, "-o", obj}, "usage error"},
        {{"apply", broken, path("script.txt"), "-o", obj}, "bad input"},
        {{"apply", mesh, path("bad_script.txt"), "-o", obj}, "bad input"},
        {{"apply", mesh, path("missing.txt"), "-o", obj}, "I/O or resource failure"},
        {{"apply", mesh, path("script.txt"), "-o", folder}, "I/O or resource failure"},
        {{"apply", mesh, path("script.txt"), "-o", obj}, "I/O or resource failure", tiny_disk},

        {{"remesh", mesh, "-o", obj, "--cage-triangles", "8"}, "ok"},
        {{"remesh", mesh, "-o", obj, "--cage-triangles", "8", "-x"}, "usage error"},
        {{"remesh", mesh, "-o", obj}, "usage error"},
        {{"remesh", mesh, "-o", png, "--cage-triangles", "8"}, "usage error"},
        {{"remesh", broken, "-o", obj, "--cage-triangles", "8"}, "bad input"},
        {{"remesh", mesh, "-o", obj, "--cage-triangles", "2"}, "bad input"},
        {{"remesh", missing, "-o", obj, "--cage-triangles", "8"}, "I/O or resource failure"},
        {{"remesh", mesh, "-o", obj, "--cage-triangles", "8", "--max-triangles", "4"}, "I/O or resource failure"},
        {{"remesh", mesh, "-o", obj, "--cage-triangles", "8"}, "I/O or resource failure", tiny_disk},

        {{"lods", mesh, "-o", obj, "--levels", "2,1,0"}, "ok"},
        {{"lods", mesh, "-o", path("set.glb"), "--budgets", "200,50"}, "ok"},
        {{"lods", mesh, "-o", obj, "--levels", "2,1,0", "-x"}, "usage error"},
        {{"lods", mesh, "-o", obj}, "usage error"},
        {{"lods", mesh, "-o", obj, "--levels", "2,,0"}, "usage error"},
        {{"lods", mesh, "-o", obj, "--levels", "1,1"}, "usage error"},
        {{"lods", mesh, "-o", obj, "--budgets", "0"}, "usage error"},
        {{"lods", mesh, "-o", obj, "--tolerances", "-1%"}, "usage error"},
        {{"lods", mesh, "-o", obj, "--levels", "1", "--budgets", "100"}, "usage error"},
        {{"lods", broken, "-o", obj, "--levels", "1"}, "bad input"},
        {{"lods", missing, "-o", obj, "--levels", "1"}, "I/O or resource failure"},
        {{"lods", mesh, "-o", folder + "/x.glb/", "--levels", "1"}, "I/O or resource failure"},
        {{"lods", mesh, "-o", obj, "--levels", "4,0", "--max-triangles", "100"}, "I/O or resource failure"},
        {{"lods", mesh, "-o", obj, "--budgets", "300000,10", "--max-triangles", "100"}, "I/O or resource failure"},
        {{"lods", mesh, "-o", obj, "--tolerances", "0.0001%,1%", "--max-triangles", "100"}, "I/O or resource failure"},
        {{"lods", mesh, "-o", path("set.glb"), "--levels", "2,1"}, "I/O or resource failure", tiny_disk},
    };

    std::set<std::pair<std::string, std::string>> covered;
    for (const Case& c : cases) {
        const cli_test::Outcome run = cli_test::run_rgbsub(c.args, c.shell_prefix);
        std::string shown = c.shell_prefix + " rgbsub";
        for (const std::string& a : c.args) shown += " '" + a + "'";
        EXPECT_EQ(run.exit_code, table.at(c.row)) << shown << " should be '" << c.row << "'; it printed:\n" << run.output;
        covered.insert({c.args.front(), c.row});
    }
    // Every subcommand went through every row.
#define RGBSUB_EXPECT_COVERED(name, description) \
    for (const auto& [meaning, code] : table) EXPECT_TRUE(covered.contains({#name, meaning})) << #name << " is not run through '" << meaning << "'";
    RGBSUB_COMMANDS(RGBSUB_EXPECT_COVERED)
#undef RGBSUB_EXPECT_COVERED
}

}  // namespace
