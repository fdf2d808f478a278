#include "io/state/detail_state.h"

#include <algorithm>
#include <stdexcept>

#include "io/state/point_records.h"
#include "io/state/state_format.h"
#include "io/state/state_line_reader.h"

namespace rgbio {

namespace {

constexpr std::string_view kLevelRecord = "detail-level";
constexpr std::string_view kFaceLevelsRecord = "detail-face-levels";
constexpr std::string_view kOriginRecord = "detail-origin";
constexpr std::size_t kLevelsPerLine = 32;

}  // namespace

bool needs_face_levels(const rgb::DetailPositions& detail) { return detail.coarsest_level() != detail.finest_level(); }

void append_detail_section(const rgb::BaseMesh& base, std::string& out, const std::function<void()>& flush_if_full) {
    const rgb::DetailPositions* detail = base.detail();
    if (!detail) return;
    const std::vector<glm::dvec3> values = detail->samples(base);
    out += "#rgb section detail " + std::to_string(values.size()) + "\n";
    if (!needs_face_levels(*detail)) {
        out += "#rgb ";
        out += kLevelRecord;
        out += ' ';
        out += std::to_string(detail->finest_level());
        out += '\n';
    } else {
        const std::span<const std::uint8_t> levels = detail->face_levels();
        for (std::size_t i = 0; i < levels.size(); i += kLevelsPerLine) {
            out += "#rgb ";
            out += kFaceLevelsRecord;
            for (std::size_t f = i; f < std::min(levels.size(), i + kLevelsPerLine); ++f) {
                out += ' ';
                out += std::to_string(levels[f]);
            }
            out += '\n';
        }
    }
    const rgb::DetailOrigin& origin = detail->origin();
    out += "#rgb ";
    out += kOriginRecord;
    for (const std::size_t count : {origin.source_triangles, origin.nearest_points}) {
        out += ' ';
        out += std::to_string(count);
    }
    out += ' ';
    out += origin.source;
    out += '\n';
    append_point_records(out, kDetailRecord, values, flush_if_full);
}

bool is_detail_record(std::string_view kind, unsigned version) {
    if (version < kDetailStateFormatVersion) return false;
    if (kind == kFaceLevelsRecord) return version >= kFaceLevelDetailStateFormatVersion;
    return kind == kDetailRecord || kind == kLevelRecord || kind == kOriginRecord;
}

SavedDetail parse_detail_section(std::span<const ObjStateLine> records, std::size_t announced, std::size_t base_faces,
                                 const ObjStateLine& section_line, const std::string& file) {
    StateLineReader header(section_line, file);
    SavedDetail saved;
    saved.section_line = section_line.line;
    bool level_seen = false, face_levels_seen = false;
    saved.values.reserve(announced);
    for (const ObjStateLine& line : records) {
        StateLineReader r(line, file);
        const std::string_view kind = r.word();
        if (kind == kLevelRecord) {
            if (level_seen || face_levels_seen) r.fail("the detail level is given twice");
            const auto level = static_cast<std::uint8_t>(r.number<unsigned>(rgb::DetailPositions::kMaxLevel));
            saved.face_levels.assign(base_faces, level);
            level_seen = true;
            r.expect_end();
        } else if (kind == kFaceLevelsRecord) {
            if (level_seen) r.fail("the detail level is given twice");
            face_levels_seen = true;
            while (!r.at_end()) {
                const auto level = static_cast<std::uint8_t>(r.number<unsigned>(rgb::DetailPositions::kMaxLevel));
                if (saved.face_levels.size() == base_faces)
                    r.fail("more detail levels than the " + std::to_string(base_faces) + " base faces");
                saved.face_levels.push_back(level);
            }
        } else if (kind == kOriginRecord) {
            saved.origin.source_triangles = r.number<std::size_t>();
            saved.origin.nearest_points = r.number<std::size_t>(announced);
            saved.origin.source = std::string(r.rest());
        } else {
            read_point_record(r, saved.values, announced, "detail positions");
        }
    }
    if (!level_seen && !face_levels_seen) header.fail("section 'detail' has no detail-level record");
    if (saved.face_levels.size() != base_faces)
        header.fail("section 'detail' gives " + std::to_string(saved.face_levels.size()) + " detail levels for " +
                    std::to_string(base_faces) + " base faces");
    if (saved.values.size() != announced)
        header.fail("section 'detail' announces " + std::to_string(announced) + " positions but holds " + std::to_string(saved.values.size()));
    return saved;
}

std::shared_ptr<const rgb::DetailPositions> detail_over(const SavedDetail& saved, std::span<const glm::dvec3> base_positions,
                                                        std::span<const rgb::Triangle> base_triangles, std::string& reason) {
    try {
        const rgb::BaseMesh base(base_positions, base_triangles);
        return std::make_shared<const rgb::DetailPositions>(base, saved.face_levels, saved.values, saved.origin);
    } catch (const std::invalid_argument& e) {
        reason = "its detail (section on line " + std::to_string(saved.section_line) + ") does not fit its base mesh (" + e.what() + ")";
        return nullptr;
    }
}

}  // namespace rgbio
