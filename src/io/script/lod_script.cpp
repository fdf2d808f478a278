#include "io/script/lod_script.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "io/files/file_text.h"
#include "io/obj/number_format.h"
#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"
#include "io/obj/text_lines.h"
#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

namespace {

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
    if constexpr (std::is_floating_point_v<T>)
        if (ec == std::errc() && !std::isfinite(value)) return false;
    return ec == std::errc() && end == word.data() + word.size();
}

class LineReader {
public:
    LineReader(const std::vector<std::string>& words, const std::string& file, std::size_t line)
        : words_(words), file_(file), line_(line) {}
    [[noreturn]] void fail(const std::string& reason) const { throw ObjError(ObjProblem::Syntax, file_, line_, reason); }
    std::size_t size() const { return words_.size(); }
    const std::string& operator[](std::size_t i) const { return words_[i]; }
    int level(std::size_t i) const {
        int value = 0;
        if (i >= words_.size() || !parse_whole(words_[i], value) || value < 0 || value > rgb::kMaxLevel)
            fail("'" + words_[0] + "' needs a whole level from 0 to " + std::to_string(rgb::kMaxLevel));
        return value;
    }
    double number(std::size_t i, const char* what) const {
        double value = 0.0;
        if (i >= words_.size() || !parse_whole(words_[i], value)) fail(std::string(what) + " is not a number");
        return value;
    }
    glm::dvec3 point(std::size_t i, const char* what) const { return {number(i, what), number(i + 1, what), number(i + 2, what)}; }

private:
    const std::vector<std::string>& words_;
    const std::string& file_;
    std::size_t line_;
};

rgb::LevelRequest level_request(const LineReader& r, rgb::RequestKind kind) {
    rgb::LevelRequest request;
    request.kind = kind;
    request.level = r.level(1);
    if (r.size() == 2) return request;
    if (r[2] != "sphere" || r.size() != 7) r.fail("expected '" + r[0] + " N sphere X Y Z R'");
    request.sphere = rgb::Sphere{r.point(3, "a sphere coordinate"), r.number(6, "the sphere radius")};
    if (!(request.sphere->radius > 0.0)) r.fail("the sphere radius must be positive");
    return request;
}

DetailEdit detail_edit(const LineReader& r, DetailCriterion criterion) {
    DetailEdit edit;
    edit.criterion = criterion;
    const char* what = criterion == DetailCriterion::MaxEdge ? "an edge length" : "a tolerance";
    if (r.size() != 2 && r.size() != 7 && r.size() != 8) r.fail("expected '" + r[0] + " AMOUNT [sphere X Y Z R [refine|coarsen|set]]'");
    const auto amount = parse_amount(r[1]);
    if (!amount) r.fail("'" + r[0] + "' needs " + what + ": a positive number, or a percentage of the bounding-box diagonal like 0.5%");
    edit.amount = *amount;
    if (r.size() == 2) return edit;
    if (r[2] != "sphere") r.fail("expected '" + r[0] + " AMOUNT sphere X Y Z R'");
    edit.sphere = rgb::Sphere{r.point(3, "a sphere coordinate"), r.number(6, "the sphere radius")};
    if (!(edit.sphere->radius > 0.0)) r.fail("the sphere radius must be positive");
    if (r.size() == 8) {
        if (r[7] == "refine") edit.kind = rgb::RequestKind::Refine;
        else if (r[7] == "coarsen") edit.kind = rgb::RequestKind::Coarsen;
        else if (r[7] != "set") r.fail("a ball's detail is refine, coarsen or set, not " + quoted_file_text(r[7]));
    }
    return edit;
}

BrushEdit brush_edit(const LineReader& r) {
    BrushEdit brush;
    if (r.size() < 4 || r.size() > 5) r.fail("expected 'brush refine|coarsen|set LEVEL RADIUS [FALLOFF]'");
    if (r[1] == "refine") brush.mode = rgb::BrushMode::Refine;
    else if (r[1] == "coarsen") brush.mode = rgb::BrushMode::Coarsen;
    else if (r[1] == "set") brush.mode = rgb::BrushMode::Set;
    else r.fail("the brush mode must be refine, coarsen or set, not " + quoted_file_text(r[1]));
    brush.level = r.level(2);
    brush.radius = r.number(3, "the brush radius");
    if (!(brush.radius > 0.0)) r.fail("the brush radius must be positive");
    if (r.size() == 5) {
        brush.falloff = r.number(4, "the falloff");
        if (brush.falloff < 0.0 || brush.falloff > 1.0) r.fail("the falloff is a fraction of the radius from 0 to 1");
    }
    return brush;
}

// "x", "yz", ...: each axis at most once.
std::uint8_t mirror_axes(const LineReader& r, std::size_t i) {
    std::uint8_t mirror = 0;
    for (char axis : r[i]) {
        const std::uint8_t bit = axis == 'x' ? kMirrorX : axis == 'y' ? kMirrorY : axis == 'z' ? kMirrorZ : 0;
        if (bit == 0 || (mirror & bit) != 0) r.fail("mirror takes the axes x, y and z, each at most once, not " + quoted_file_text(r[i]));
        mirror |= bit;
    }
    return mirror;
}

DabEdit dab_edit(const LineReader& r) {
    std::size_t words = r.size();
    const bool mirrored = words >= 6 && r[words - 2] == "mirror";
    if (mirrored) words -= 2;
    if (words != 4 && words != 7) r.fail("expected 'dab X Y Z [VX VY VZ] [mirror AXES]'");
    DabEdit dab{r.point(1, "a dab coordinate"), std::nullopt, mirrored ? mirror_axes(r, words + 1) : std::uint8_t{0}};
    if (words == 7) {
        dab.view = r.point(4, "a view direction component");
        // A length that underflows to 0 or a subnormal (0 0 -1e-300), or overflows, gives no direction to paint along.
        if (!std::isnormal(glm::length(*dab.view)))
            r.fail("the view direction must not be zero: its length must be a normal positive double (not 0, subnormal or "
                   "infinite)");
    }
    return dab;
}

const char* mode_name(rgb::BrushMode mode) {
    switch (mode) {
        case rgb::BrushMode::Refine: return "refine";
        case rgb::BrushMode::Coarsen: return "coarsen";
        case rgb::BrushMode::Set: return "set";
    }
    return "?";
}

}  // namespace

std::vector<ScriptLine> parse_lod_script(const std::string& text, const std::string& file) {
    std::vector<ScriptLine> script;
    bool brush_given = false;
    // Lines end at LF, CRLF or a lone CR, as in OBJ files.
    for_each_line(text, [&](std::size_t number, std::string_view content) {
        const std::string line(content);
        const std::vector<std::string> words = split_words(line);
        if (words.empty() || words[0].starts_with('#')) return;
        const LineReader r(words, file, number);
        ScriptLine entry;
        entry.line = number;
        entry.text = line.substr(0, line.find_last_not_of(" \t\r") + 1);
        if (words[0] == "level") {
            entry.edit = level_request(r, rgb::RequestKind::Set);
        } else if (words[0] == "refine") {
            entry.edit = level_request(r, rgb::RequestKind::Refine);
        } else if (words[0] == "coarsen") {
            entry.edit = level_request(r, rgb::RequestKind::Coarsen);
        } else if (words[0] == "budget") {
            std::size_t triangles = 0;
            if (words.size() != 2 || !parse_whole(words[1], triangles) || triangles == 0 || triangles > kMaxBudget)
                r.fail("'budget' needs a whole number of triangles from 1 to " + std::to_string(kMaxBudget));
            entry.edit = BudgetEdit{triangles};
        } else if (words[0] == "max-edge") {
            entry.edit = detail_edit(r, DetailCriterion::MaxEdge);
        } else if (words[0] == "tolerance") {
            entry.edit = detail_edit(r, DetailCriterion::Tolerance);
        } else if (words[0] == "brush") {
            entry.edit = brush_edit(r);
            brush_given = true;
        } else if (words[0] == "dab") {
            if (!brush_given) r.fail("a dab needs a 'brush' line before it");
            entry.edit = dab_edit(r);
        } else {
            r.fail("unknown command " + quoted_file_text(words[0]) +
                   " (expected level, refine, coarsen, budget, max-edge, tolerance, brush or dab)");
        }
        script.push_back(std::move(entry));
    });
    return script;
}

std::vector<ScriptLine> read_lod_script(const std::string& file) { return parse_lod_script(read_text_file(file), file); }


rgb::Dab ScriptRunner::dab(const DabEdit& edit) const {
    rgb::Dab dab;
    dab.mode = brush_.mode;
    dab.level = brush_.level;
    dab.radius = brush_.radius;
    dab.falloff = brush_.falloff;
    dab.centre = edit.centre;
    dab.view = edit.view;
    return dab;
}

rgb::RequestStats ScriptRunner::run(rgb::Mesh& mesh, const ScriptLine& line) {
    reached_error_.reset();
    if (const auto* detail = std::get_if<DetailEdit>(&line.edit)) {
        const DetailOutcome outcome = apply_detail_edit(mesh, *detail, max_triangles_);
        reached_error_ = outcome.reached_error;
        return {outcome.report.splits, outcome.report.removals, outcome.report.level_cap_bound};
    }
    if (const auto* request = std::get_if<rgb::LevelRequest>(&line.edit)) return rgb::apply_request(mesh, *request);
    if (const auto* brush = std::get_if<BrushEdit>(&line.edit)) {
        brush_ = *brush;
        return {};
    }
    if (const auto* dab_line = std::get_if<DabEdit>(&line.edit)) {
        rgb::RequestStats stats;
        for (const rgb::Dab& image : with_mirror_images(dab(*dab_line), dab_line->mirror)) stats += rgb::apply_dab(mesh, image);
        return stats;
    }
    const auto& budget = std::get<BudgetEdit>(line.edit);
    rgb::LodSettings settings;
    settings.max_triangles = budget.triangles;
    settings.uniform_start = true;  // a script line runs to its end
    // On a cage with detail the splits go where the surface departs most from the dense surface.
    if (mesh.base().detail()) settings.value = rgb::on_mesh(rgb::detail_error_value(mesh.shared_base()));
    rgb::LodDriver driver(mesh, settings);
    driver.run();
    return {driver.report().splits, driver.report().removals, driver.report().level_cap_bound};
}

std::string format_brush_line(const BrushEdit& brush) {
    std::string out = std::string("brush ") + mode_name(brush.mode) + " " + std::to_string(brush.level);
    append_double(out, brush.radius);
    append_double(out, brush.falloff);
    return out;
}

std::string format_detail_line(const DetailEdit& edit) {
    std::string out = edit.criterion == DetailCriterion::MaxEdge ? "max-edge " : "tolerance ";
    out += format_amount(edit.amount);
    if (!edit.sphere) return out;
    out += " sphere";
    for (int i = 0; i < 3; ++i) append_double(out, edit.sphere->centre[i]);
    append_double(out, edit.sphere->radius);
    if (edit.kind == rgb::RequestKind::Refine) out += " refine";
    if (edit.kind == rgb::RequestKind::Coarsen) out += " coarsen";
    return out;
}

std::vector<rgb::Dab> with_mirror_images(const rgb::Dab& dab, std::uint8_t mirror) {
    std::vector<rgb::Dab> dabs{dab};
    for (std::uint8_t planes = 1; planes <= 7; ++planes) {
        if ((planes & mirror) != planes) continue;
        rgb::Dab image = dab;
        for (int axis = 0; axis < 3; ++axis) {
            if ((planes & (1 << axis)) == 0) continue;
            image.centre[axis] = -image.centre[axis];
            if (image.view) (*image.view)[axis] = -(*image.view)[axis];
        }
        dabs.push_back(image);
    }
    return dabs;
}

std::string format_dab_line(const DabEdit& dab) {
    std::string out = "dab";
    for (int i = 0; i < 3; ++i) append_double(out, dab.centre[i]);
    if (dab.view)
        for (int i = 0; i < 3; ++i) append_double(out, (*dab.view)[i]);
    if (dab.mirror != 0) {
        out += " mirror ";
        for (int axis = 0; axis < 3; ++axis)
            if ((dab.mirror & (1 << axis)) != 0) out += "xyz"[axis];
    }
    return out;
}

}  // namespace rgbio
