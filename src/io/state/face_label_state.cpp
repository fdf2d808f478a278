#include "io/state/face_label_state.h"

#include <algorithm>
#include <charconv>

#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"
#include "rgb/mesh/face_location.h"

namespace rgbio {

namespace {

constexpr std::string_view kSection = "face-labels";
constexpr std::string_view kTableRecord[3] = {"material", "group", "object"};
constexpr std::size_t kFacesPerLine = 8;

constexpr std::string_view kBlanks = " \t\r";

std::string_view trimmed(std::string_view text) {
    text.remove_prefix(std::min(text.find_first_not_of(kBlanks), text.size()));
    text.remove_suffix(text.size() - std::min(text.find_last_not_of(kBlanks) + 1, text.size()));
    return text;
}

// The first word of `text`, removed from it.
std::string_view take_word(std::string_view& text) {
    text = trimmed(text);
    const std::string_view word = text.substr(0, std::min(text.find_first_of(kBlanks), text.size()));
    text.remove_prefix(word.size());
    return word;
}

const FaceLabels& table(const BaseFaceLabels& labels, int t) {
    return t == 0 ? labels.materials : (t == 1 ? labels.groups : labels.objects);
}

}  // namespace

void append_face_label_section(const BaseFaceLabels& labels, std::size_t base_faces, std::string& out) {
    if (labels.empty()) return;
    out += "#rgb section " + std::string(kSection) + " " + std::to_string(base_faces) + "\n";
    for (int t = 0; t < 3; ++t)
        for (const std::string& name : table(labels, t).names) out += "#rgb " + std::string(kTableRecord[t]) + " " + name + "\n";
    for (std::size_t f = 0; f < base_faces; f += kFacesPerLine) {
        out += "#rgb l";
        for (std::size_t g = f; g < std::min(base_faces, f + kFacesPerLine); ++g) {
            for (int t = 0; t < 3; ++t) {
                const FaceLabels& labels_t = table(labels, t);
                const std::uint32_t i = labels_t.empty() ? kNoIndex : labels_t.of_triangle[g];
                out += ' ' + std::to_string(i == kNoIndex ? 0u : i + 1);
            }
            out += ' ' + std::to_string(labels.smoothing_groups.empty() ? 0u : labels.smoothing_groups[g]);
        }
        out += '\n';
    }
}

bool FaceLabelSectionReader::take(const ObjStateLine& line) {
    auto fail = [&](const std::string& reason) {
        throw ObjError(ObjProblem::BadState, file_, line.line, "rgbsub state: " + reason);
    };
    std::string_view rest = line.text;
    const std::string_view kind = take_word(rest);
    if (kind == "section" || kind == "end") {
        inside_ = take_word(rest) == kSection;
        if (!inside_) return false;
        if (seen_) fail("section '" + std::string(kSection) + "' appears twice");
        seen_ = true;
        const std::string_view count = take_word(rest);
        const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), announced_);
        if (ec != std::errc() || end != count.data() + count.size() || !trimmed(rest).empty())
            fail("expected the number of base faces after 'section face-labels'");
        return true;
    }
    if (!inside_) return false;
    for (int t = 0; t < 3; ++t)
        if (kind == kTableRecord[t]) {
            if (trimmed(rest).empty()) fail("a " + std::string(kind) + " name is missing");
            names_[t].emplace_back(trimmed(rest));
            return true;
        }
    if (kind != "l") return false;
    while (!trimmed(rest).empty()) {
        std::uint32_t values[4];
        for (std::uint32_t& value : values) {
            const std::string_view word = take_word(rest);
            if (word.empty()) fail("a face's labels need four numbers (material, group, object, smoothing group)");
            const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
            if (ec != std::errc() || end != word.data() + word.size())
                fail("expected a label index, found " + quoted_file_text(word));
        }
        // Bounded by the announced count, so that a forged file cannot make the lists grow without end.
        if (smoothing_groups_.size() == announced_) fail("more face labels than the " + std::to_string(announced_) + " announced");
        for (int t = 0; t < 3; ++t) indices_[t].push_back(values[t]);
        smoothing_groups_.push_back(values[3]);
    }
    return true;
}

BaseFaceLabels FaceLabelSectionReader::finish(std::size_t base_faces, const ObjStateLine& last) const {
    BaseFaceLabels labels;
    if (!seen_) return labels;
    auto fail = [&](const std::string& reason) {
        throw ObjError(ObjProblem::BadState, file_, last.line, "rgbsub state: section 'face-labels' " + reason);
    };
    if (announced_ != base_faces)
        fail("announces " + std::to_string(announced_) + " faces, the base mesh has " + std::to_string(base_faces));
    if (smoothing_groups_.size() != base_faces)
        fail("holds labels for " + std::to_string(smoothing_groups_.size()) + " of " + std::to_string(base_faces) + " base faces");
    FaceLabels* tables[3] = {&labels.materials, &labels.groups, &labels.objects};
    for (int t = 0; t < 3; ++t) {
        const bool any = std::any_of(indices_[t].begin(), indices_[t].end(), [](std::uint32_t i) { return i != 0; });
        if (!any && names_[t].empty()) continue;
        tables[t]->names = names_[t];
        tables[t]->of_triangle.reserve(base_faces);
        for (std::uint32_t i : indices_[t]) {
            if (i > names_[t].size())
                fail("names " + std::string(kTableRecord[t]) + " " + std::to_string(i) + " of " + std::to_string(names_[t].size()));
            tables[t]->of_triangle.push_back(i == 0 ? kNoIndex : i - 1);
        }
    }
    if (std::any_of(smoothing_groups_.begin(), smoothing_groups_.end(), [](std::uint32_t s) { return s != 0; }))
        labels.smoothing_groups = smoothing_groups_;
    return labels;
}

BaseFaceLabels body_labels(const rgb::Mesh& mesh, const ObjRecords& records) {
    BaseFaceLabels labels;
    if (!records.polygons.has_any_labels()) return labels;
    const std::vector<std::string>* file_names[3] = {&records.material_names, &records.group_names, &records.object_names};
    std::uint32_t ObjPolygon::*field[3] = {&ObjPolygon::material, &ObjPolygon::group, &ObjPolygon::object};
    const std::size_t base_faces = mesh.base().num_faces();
    std::vector<bool> seen(base_faces, false);
    std::vector<std::uint32_t> of_base[3], smoothing(base_faces, 0);
    for (auto& indices : of_base) indices.assign(base_faces, kNoIndex);
    bool any[4] = {false, false, false, false};
    std::size_t slot = 0;
    for (rgb::FaceId f : mesh.faces()) {
        const ObjPolygon polygon = records.polygons[slot++];
        const std::uint32_t b = rgb::base_face_of(mesh, f);
        if (seen[b]) continue;
        seen[b] = true;
        for (int t = 0; t < 3; ++t) {
            of_base[t][b] = polygon.*field[t];
            any[t] = any[t] || polygon.*field[t] != kNoIndex;
        }
        smoothing[b] = polygon.smoothing_group;
        any[3] = any[3] || polygon.smoothing_group != 0;
    }
    FaceLabels* tables[3] = {&labels.materials, &labels.groups, &labels.objects};
    for (int t = 0; t < 3; ++t)
        if (any[t]) *tables[t] = {*file_names[t], std::move(of_base[t])};
    if (any[3]) labels.smoothing_groups = std::move(smoothing);
    return labels;
}

std::optional<std::string> label_mismatch(const rgb::Mesh& mesh, const BaseFaceLabels& labels, const ObjRecords& records) {
    const std::vector<std::string>* file_names[3] = {&records.material_names, &records.group_names, &records.object_names};
    std::uint32_t ObjPolygon::*field[3] = {&ObjPolygon::material, &ObjPolygon::group, &ObjPolygon::object};
    // Neither side has a label: every face agrees.
    if (labels.empty() && !records.polygons.has_any_labels()) return std::nullopt;
    auto name = [](const std::vector<std::string>& names, std::uint32_t i) { return i == kNoIndex ? std::string() : names[i]; };
    std::size_t slot = 0;
    for (rgb::FaceId f : mesh.faces()) {
        const ObjPolygon& polygon = records.polygons[slot++];
        const std::uint32_t base_face = rgb::base_face_of(mesh, f);
        for (int t = 0; t < 3; ++t) {
            const FaceLabels& state = table(labels, t);
            const std::string expected = state.empty() ? std::string() : name(state.names, state.of_triangle[base_face]);
            if (name(*file_names[t], polygon.*field[t]) != expected)
                return "the face on line " + std::to_string(polygon.line) + " has another " + std::string(kTableRecord[t]) + " (" +
                       quoted_file_text(name(*file_names[t], polygon.*field[t])) + ") than its base face (" +
                       quoted_file_text(expected) + ")";
        }
        const std::uint32_t smoothing = labels.smoothing_groups.empty() ? 0 : labels.smoothing_groups[base_face];
        if (polygon.smoothing_group != smoothing)
            return "the face on line " + std::to_string(polygon.line) + " has smoothing group " +
                   std::to_string(polygon.smoothing_group) + ", its base face " + std::to_string(smoothing);
    }
    return std::nullopt;
}

}  // namespace rgbio
