#include "io/script/lod_set.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "io/script/triangle_limit.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

namespace {

constexpr std::size_t kMaxLodBudget = 500'000'000;  // as a script's budget line

std::vector<std::string> list_entries(const std::string& list) {
    std::vector<std::string> entries;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = list.find(',', start);
        entries.push_back(list.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (entries.back().empty()) throw std::invalid_argument("an empty entry in '" + list + "'");
        if (comma == std::string::npos) return entries;
        start = comma + 1;
    }
}

// A whole number of digits only, at most `max`; nullopt otherwise.
std::optional<std::size_t> whole_number(const std::string& text, std::size_t max) {
    if (text.empty() || text.size() > 12 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    const std::size_t value = std::stoull(text);
    if (value > max) return std::nullopt;
    return value;
}

}  // namespace

const char* lod_set_option(LodSetCriterion criterion) {
    switch (criterion) {
        case LodSetCriterion::Levels: return "--levels";
        case LodSetCriterion::Budgets: return "--budgets";
        case LodSetCriterion::Tolerances: return "--tolerances";
    }
    return "";
}

std::vector<ScriptLine> lod_set_requests(LodSetCriterion criterion, const std::string& list, const rgb::Mesh& mesh) {
    struct Entry {
        double fineness;  // larger is finer
        ScriptLine line;
    };
    std::vector<Entry> entries;
    for (const std::string& text : list_entries(list)) {
        ScriptLine line;
        line.text = text;
        double fineness = 0.0;
        if (criterion == LodSetCriterion::Levels) {
            const auto level = whole_number(text, static_cast<std::size_t>(rgb::kMaxLevel));
            if (!level) throw std::invalid_argument("'" + text + "' is no level from 0 to " + std::to_string(rgb::kMaxLevel));
            rgb::LevelRequest request;
            request.level = static_cast<int>(*level);
            line.edit = request;
            fineness = static_cast<double>(*level);
        } else if (criterion == LodSetCriterion::Budgets) {
            const auto triangles = whole_number(text, kMaxLodBudget);
            if (!triangles || *triangles == 0)
                throw std::invalid_argument("'" + text + "' is no whole number of triangles from 1 to " + std::to_string(kMaxLodBudget));
            line.edit = BudgetEdit{*triangles};
            fineness = static_cast<double>(*triangles);
        } else {
            const std::optional<Amount> amount = parse_amount(text);
            if (!amount)
                throw std::invalid_argument("'" + text + "' is no positive length or percentage of the bounding-box diagonal");
            line.edit = DetailEdit{DetailCriterion::Tolerance, *amount, rgb::RequestKind::Set, std::nullopt};
            fineness = -world_amount(mesh, *amount);
        }
        for (const Entry& e : entries)
            if (e.fineness == fineness) throw std::invalid_argument("'" + e.line.text + "' and '" + text + "' ask for the same level");
        entries.push_back({fineness, std::move(line)});
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.fineness > b.fineness; });
    std::vector<ScriptLine> out;
    for (Entry& e : entries) out.push_back(std::move(e.line));
    return out;
}

rgb::Mesh lod_set_level(const rgb::Mesh& input, const ScriptLine& request, std::size_t max_triangles) {
    rgb::Mesh mesh = input;
    if (const auto* level = std::get_if<rgb::LevelRequest>(&request.edit)) check_request_size(mesh, *level, max_triangles);
    if (const auto* budget = std::get_if<BudgetEdit>(&request.edit)) check_budget_size(budget->triangles, max_triangles);
    ScriptRunner runner(max_triangles);
    runner.run(mesh, request);
    return mesh;
}

std::vector<double> switch_coverage(const std::vector<double>& errors, double size) {
    std::vector<double> coverage(errors.size(), 0.0);
    for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
        const double next = errors[i + 1];
        const double span = next > 0.0 ? size / next / kCoverageScreenPixels : std::numeric_limits<double>::infinity();
        coverage[i] = std::min({1.0, span * span, i > 0 ? coverage[i - 1] : 1.0});
    }
    return coverage;
}

bool positions_nested(std::vector<glm::dvec3> coarser, std::vector<glm::dvec3> finer) {
    const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    std::sort(coarser.begin(), coarser.end(), less);
    std::sort(finer.begin(), finer.end(), less);
    return std::includes(finer.begin(), finer.end(), coarser.begin(), coarser.end(), less);
}

std::string lod_file_name(const std::string& output, std::size_t level) {
    const std::filesystem::path path(output);
    std::filesystem::path name = path.stem();
    name += "_LOD" + std::to_string(level);
    name += path.extension();
    return (path.parent_path() / name).string();
}

}  // namespace rgbio
