#include "cli/lod_script.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "io/obj_error.h"
#include "io/obj_reader.h"
#include "rgb/lod_driver.h"

namespace cli {

namespace {

constexpr int kMaxLevel = 20;
constexpr std::size_t kMaxBudget = 500'000'000;

std::vector<std::string> split_words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

template <class T>
bool parse_whole(const std::string& word, T& value) {
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    return ec == std::errc() && end == word.data() + word.size();
}

}  // namespace

std::vector<LodEdit> parse_lod_script(const std::string& text, const std::string& file) {
    std::vector<LodEdit> edits;
    std::istringstream in(text);
    std::size_t number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        auto fail = [&](const std::string& reason) { return rgbio::ObjError(rgbio::ObjProblem::Syntax, file, number, reason); };
        const std::vector<std::string> words = split_words(line);
        if (words.empty() || words[0].starts_with('#')) continue;
        if (words[0] != "level" && words[0] != "budget")
            throw fail("unknown command '" + words[0] + "' (expected 'level N [sphere X Y Z R]' or 'budget TRIANGLES')");
        LodEdit edit;
        edit.line = number;
        edit.text = line.substr(0, line.find_last_not_of(" \t\r") + 1);
        if (words[0] == "budget") {
            std::size_t triangles = 0;
            if (words.size() != 2 || !parse_whole(words[1], triangles) || triangles == 0 || triangles > kMaxBudget)
                throw fail("'budget' needs a whole number of triangles from 1 to " + std::to_string(kMaxBudget));
            edit.budget = triangles;
            edits.push_back(std::move(edit));
            continue;
        }
        if (words.size() < 2 || !parse_whole(words[1], edit.level) || edit.level < 0 || edit.level > kMaxLevel)
            throw fail("'level' needs a whole number from 0 to " + std::to_string(kMaxLevel));
        if (words.size() > 2) {
            double values[4];
            if (words[2] != "sphere" || words.size() != 7) throw fail("expected 'level N sphere X Y Z R'");
            for (int i = 0; i < 4; ++i)
                if (!parse_whole(words[3 + i], values[i]) || !std::isfinite(values[i]))
                    throw fail("sphere value '" + words[3 + i] + "' is not a number");
            if (values[3] <= 0) throw fail("the sphere radius must be positive");
            edit.sphere = std::make_pair(glm::dvec3(values[0], values[1], values[2]), values[3]);
        }
        edits.push_back(std::move(edit));
    }
    return edits;
}

std::vector<LodEdit> read_lod_script(const std::string& file) {
    return parse_lod_script(rgbio::read_text_file(file), file);
}

namespace {
struct OperationCounter : rgb::MeshObserver {
    rgb::SetLevelStats stats;
    void vertex_added(const rgb::Mesh&, rgb::VertexId, rgb::VertexId, rgb::VertexId) override { ++stats.splits; }
    void vertex_removed(const rgb::Mesh&, rgb::VertexId) override { ++stats.removals; }
};
}  // namespace

rgb::SetLevelStats apply_lod_edit(rgb::Mesh& mesh, const LodEdit& edit) {
    if (edit.budget) {
        rgb::LodSettings settings;
        settings.excess = rgb::edge_length_excess([](const glm::dvec3&) { return 0.0; });
        settings.max_triangles = *edit.budget;
        OperationCounter counter;
        mesh.add_observer(&counter);
        rgb::LodDriver(mesh, settings).run();
        mesh.remove_observer(&counter);
        return counter.stats;
    }
    const rgb::Region region = edit.sphere ? rgb::Region::sphere(edit.sphere->first, edit.sphere->second) : rgb::Region::everywhere();
    return rgb::set_level(mesh, region, edit.level);
}

}  // namespace cli
