// Vertex colours through save and load (issue 12): a refined save keeps the base vertices' colours in
// the state's base-colours section, so load -> refine -> save -> load -> level 0 gives back the
// input's colours bit for bit and a resumed mesh writes the colours the saved one wrote; the v lines'
// colours are checked against the section (an edit elsewhere wins); a malformed section is an error
// naming its line; a file without the section still loads.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/base_attributes.h"
#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "scratch_folder.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

constexpr int kColumns = 4, kRows = 3;

// The colour of grid vertex i, needing 17 significant digits.
glm::dvec3 input_colour(int i) { return {std::sqrt(2.0 + i) / 7.0, std::log(3.0 + i) / 5.0, 1.0 / (3.0 + i)}; }

// A 4 x 3 grid with bumps, its colours written with 17 digits ("%.17g", not the shortest form).
std::string coloured_grid() {
    std::string text;
    char buffer[160];
    for (int y = 0; y <= kRows; ++y)
        for (int x = 0; x <= kColumns; ++x) {
            const glm::dvec3 c = input_colour(y * (kColumns + 1) + x);
            std::snprintf(buffer, sizeof buffer, "v %d %d %d %.17g %.17g %.17g\n", x, y, (x * y) % 3, c.r, c.g, c.b);
            text += buffer;
        }
    for (int y = 0; y < kRows; ++y)
        for (int x = 0; x < kColumns; ++x) {
            const int a = y * (kColumns + 1) + x + 1, b = a + 1, c = a + kColumns + 1, d = c + 1;
            text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\n";
            text += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
        }
    return text;
}

// The colours of a file's v lines, read with strtod (correctly rounded, as the file's digits say).
std::vector<glm::dvec3> v_line_colours(const std::string& text) {
    std::vector<glm::dvec3> colours;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (!line.starts_with("v ")) continue;
        std::istringstream words(line.substr(2));
        std::vector<std::string> numbers;
        for (std::string w; words >> w;) numbers.push_back(w);
        EXPECT_EQ(numbers.size(), 6u) << line;
        if (numbers.size() != 6) continue;
        colours.push_back({std::strtod(numbers[3].c_str(), nullptr), std::strtod(numbers[4].c_str(), nullptr),
                           std::strtod(numbers[5].c_str(), nullptr)});
    }
    return colours;
}

// The lines of `text` starting with `start`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& start) {
    std::vector<std::string> found;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.starts_with(start)) found.push_back(line);
    return found;
}

class ColourRoundTrip : public test::ScratchFolder {
protected:
    // The grid refined in a ball to level 3 and everywhere once more, saved with `positions`.
    std::string refined_save(SavedPositions positions) {
        write("in.obj", coloured_grid());
        asset_ = load_asset(path("in.obj"));
        rgbtest::set_level(asset_.mesh, 3, rgb::Sphere{{2, 1.5, 0}, 1.2});
        rgb::LevelRequest everywhere;
        everywhere.kind = rgb::RequestKind::Refine;
        everywhere.level = 1;
        rgb::apply_request(asset_.mesh, everywhere);
        SaveOptions options;
        options.attributes = asset_.attributes;
        options.positions = positions;
        save_mesh(asset_.mesh, path("saved.obj"), options);
        return read(path("saved.obj"));
    }
    LoadedAsset asset_;
};

TEST_F(ColourRoundTrip, ARefinedSaveResumesWithItsColoursAndLevelZeroGivesBackTheInputsBitForBit) {
    std::vector<glm::dvec3> input;
    for (int i = 0; i < (kColumns + 1) * (kRows + 1); ++i) input.push_back(input_colour(i));
    for (const SavedPositions positions : {SavedPositions::Displayed, SavedPositions::Limit}) {
        const std::string text = refined_save(positions);
        ASSERT_EQ(lines_starting(text, "#rgb section base-colours ").size(), 1u);
        std::vector<std::string> warnings;
        LoadedAsset resumed = load_asset(path("saved.obj"), &warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        ASSERT_EQ(resumed.mesh.num_vertices(), asset_.mesh.num_vertices());
        ASSERT_GT(resumed.mesh.num_vertices(), input.size()) << "the state was used";
        EXPECT_EQ(resumed.attributes->colours, input);

        // The resumed mesh writes the v lines (positions and colours) of the saved one.
        SaveOptions options;
        options.attributes = resumed.attributes;
        options.positions = positions;
        EXPECT_EQ(lines_starting(format_obj(resumed.mesh, options), "v "), lines_starting(text, "v "));

        // At level 0 the displayed colours are the base colours (limit ones would be averaged).
        rgbtest::set_level(resumed.mesh, 0);
        options.state = false;
        options.positions = SavedPositions::Displayed;
        EXPECT_EQ(v_line_colours(format_obj(resumed.mesh, options)), input);
    }
}

TEST_F(ColourRoundTrip, ColoursEditedElsewhereWinOverTheState) {
    std::string text = refined_save(SavedPositions::Displayed);
    // Another program repaints the last vertex: the state no longer gives the file's colours.
    const std::size_t last_v = text.rfind("\nv ") + 1, end = text.find('\n', last_v);
    std::istringstream words(text.substr(last_v + 2, end - last_v - 2));
    std::string x, y, z;
    words >> x >> y >> z;
    text.replace(last_v, end - last_v, "v " + x + " " + y + " " + z + " 0.5 0.5 0.5");
    write("edited.obj", text);
    std::vector<std::string> warnings;
    const LoadedAsset edited = load_asset(path("edited.obj"), &warnings);
    EXPECT_TRUE(test::has_warning(warnings, "vertex colours differ from the ones its base-colours section gives"));
    EXPECT_EQ(edited.mesh.num_vertices(), edited.mesh.num_base_vertices()) << "loaded as the plain mesh of its lines";
    EXPECT_EQ(edited.attributes->colours.back(), glm::dvec3(0.5));

    // Colours removed elsewhere stay removed; the state still restores the mesh.
    std::string plain;
    std::istringstream lines(refined_save(SavedPositions::Displayed));
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("v ")) line = line.substr(0, line.find(' ', line.find(' ', line.find(' ', 2) + 1) + 1));
        plain += line + '\n';
    }
    write("colourless.obj", plain);
    warnings.clear();
    const LoadedAsset colourless = load_asset(path("colourless.obj"), &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(colourless.mesh.num_vertices(), asset_.mesh.num_vertices());
    EXPECT_TRUE(colourless.attributes->colours.empty());
}

TEST_F(ColourRoundTrip, AFileWithoutTheSectionStillLoads) {
    // As an older rgbsub wrote it: the state without the base-colours section.
    std::string old;
    std::istringstream lines(refined_save(SavedPositions::Displayed));
    for (std::string line; std::getline(lines, line);)
        if (!line.starts_with("#rgb section base-colours") && !line.starts_with("#rgb colour")) old += line + '\n';
    write("old.obj", old);
    std::vector<std::string> warnings;
    const LoadedAsset loaded = load_asset(path("old.obj"), &warnings);
    EXPECT_EQ(loaded.mesh.num_vertices(), asset_.mesh.num_vertices());
    EXPECT_TRUE(loaded.attributes->colours.empty());
    EXPECT_TRUE(test::has_warning(warnings, "ignored the file's vertex colours: the file is a refined mesh whose rgbsub state has no "
                                            "base-colours section"));
}

// A malformed section is an ObjError naming the file and the line at fault.
TEST_F(ColourRoundTrip, AMalformedSectionIsAnErrorNamingItsLine) {
    const std::string text = refined_save(SavedPositions::Displayed);
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::size_t section = 0;
    while (!lines[section].starts_with("#rgb section base-colours ")) ++section;
    const std::string announced = lines[section].substr(std::string("#rgb section base-colours ").size());
    ASSERT_EQ(announced, std::to_string((kColumns + 1) * (kRows + 1)));
    struct Tampering {
        std::string what;
        std::size_t line;  // 0-based index of the line replaced by `replacement`
        std::string replacement;
        std::size_t error_line;  // 0-based
        std::string reason;
    };
    const Tampering cases[] = {
        {"a word for a number", section + 1, "#rgb colour 0.5 red 0.5", section + 1, "expected a number, found 'red'"},
        {"a colour cut short", section + 1, "#rgb colour 0.5 0.5", section + 1, "the line ends too early"},
        {"one base vertex more announced", section, "#rgb section base-colours 21", section,
         "announces 21 colours, the base mesh has 20 vertices"},
        {"a record line dropped", section + 1, "", section, "announces 20 colours but holds 12"},
        {"colours before their section", section, "#rgb colour 1 1 1", section, "vertex colours outside their section"},
    };
    for (const Tampering& t : cases) {
        std::string forged;
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (i != t.line || !t.replacement.empty()) forged += (i == t.line ? t.replacement : lines[i]) + '\n';
        write("forged.obj", forged);
        try {
            load_asset(path("forged.obj"));
            ADD_FAILURE() << t.what << ": no error";
        } catch (const ObjError& e) {
            EXPECT_EQ(e.problem(), ObjProblem::BadState) << t.what;
            EXPECT_EQ(e.line(), t.error_line + 1) << t.what << ": " << e.what();
            EXPECT_NE(std::string(e.what()).find(path("forged.obj") + ":" + std::to_string(t.error_line + 1) + ": "), std::string::npos)
                << e.what();
            EXPECT_NE(e.reason().find(t.reason), std::string::npos) << t.what << ": " << e.reason();
        }
    }
}

}  // namespace
}  // namespace rgbio
