#include "io/state/detail_state.h"

#include <stdexcept>

#include "io/state/point_records.h"
#include "io/state/state_line_reader.h"

namespace rgbio {

void append_detail_section(const rgb::BaseMesh& base, std::string& out, const std::function<void()>& flush_if_full) {
    const rgb::DetailPositions* detail = base.detail();
    if (!detail) return;
    const std::vector<glm::dvec3> values = detail->samples(base);
    out += "#rgb section detail " + std::to_string(values.size()) + "\n";
    out += "#rgb detail-level " + std::to_string(detail->level()) + "\n";
    const rgb::DetailOrigin& origin = detail->origin();
    out += "#rgb detail-origin " + std::to_string(origin.source_triangles) + " " + std::to_string(origin.nearest_points) + " " +
           origin.source + "\n";
    append_point_records(out, kDetailRecord, values, flush_if_full);
}

bool is_detail_record(std::string_view kind) { return kind == kDetailRecord || kind == "detail-level" || kind == "detail-origin"; }

SavedDetail parse_detail_section(std::span<const ObjStateLine> records, std::size_t announced, const ObjStateLine& section_line,
                                 const std::string& file) {
    StateLineReader header(section_line, file);
    SavedDetail saved;
    bool level_seen = false;
    saved.values.reserve(announced);
    for (const ObjStateLine& line : records) {
        StateLineReader r(line, file);
        const std::string_view kind = r.word();
        if (kind == "detail-level") {
            if (level_seen) r.fail("the detail level is given twice");
            saved.level = static_cast<int>(r.number<unsigned>(rgb::DetailPositions::kMaxLevel));
            level_seen = true;
            r.expect_end();
        } else if (kind == "detail-origin") {
            saved.origin.source_triangles = r.number<std::size_t>();
            saved.origin.nearest_points = r.number<std::size_t>(announced);
            saved.origin.source = std::string(r.rest());
        } else {
            read_point_record(r, saved.values, announced, "detail positions");
        }
    }
    if (!level_seen) header.fail("section 'detail' has no detail-level record");
    if (saved.values.size() != announced)
        header.fail("section 'detail' announces " + std::to_string(announced) + " positions but holds " + std::to_string(saved.values.size()));
    return saved;
}

std::shared_ptr<const rgb::DetailPositions> detail_over(const SavedDetail& saved, std::span<const glm::dvec3> base_positions,
                                                        std::span<const rgb::Triangle> base_triangles, std::string& reason) {
    try {
        const rgb::BaseMesh base(base_positions, base_triangles);
        return std::make_shared<const rgb::DetailPositions>(base, saved.level, saved.values, saved.origin);
    } catch (const std::invalid_argument& e) {
        reason = std::string("its detail does not fit its base mesh (") + e.what() + ")";
        return nullptr;
    }
}

}  // namespace rgbio
