// The editor's crease tool (crease_tool.h): drags that tag or untag base edges, and retagging as an
// undoable step.
#include <stdexcept>

#include "app/editor.h"

namespace app {

bool Editor::set_sharp_features(const rgb::SharpFeatures& features, std::string label) {
    if (busy()) return false;
    try {
        document_.set_sharp_features(features, label);
    } catch (const std::invalid_argument& refused) {
        report(refused.what(), true);
        return false;
    }
    report(label, false);
    return true;
}

void Editor::begin_crease_drag(bool untag) {
    crease_drag_.emplace(untag);
    crease_hit_.reset();
    crease_last_px_ = mouse_;
    crease_drag_to(mouse_);
}

// Samples the cursor's path a few pixels apart, so that a fast drag misses no edge it crosses.
void Editor::crease_drag_to(glm::vec2 px) {
    const float step = std::max(1.0f, 0.5f * crease_tool_.reach_px);
    const glm::vec2 from = crease_last_px_;
    const int samples = std::max(1, static_cast<int>(glm::length(px - from) / step));
    for (int i = 1; i <= samples; ++i) {
        const glm::vec2 at = from + (px - from) * (static_cast<float>(i) / static_cast<float>(samples));
        crease_hit_ = pick(at);
        if (!crease_hit_) continue;
        const double reach = crease_tool_.reach_px * camera_.world_per_pixel(camera_.depth_of(crease_hit_->point), viewport_);
        if (auto edge = base_edge_near(document_.mesh(), document_.geometry(), *crease_hit_, reach))
            crease_drag_->touch(*edge);
    }
    crease_last_px_ = px;
}

void Editor::end_crease_drag() {
    const CreaseDrag drag = std::move(*crease_drag_);
    crease_drag_.reset();
    crease_hit_.reset();
    const std::optional<rgb::SharpFeatures> tags = drag.result(document_.mesh().base().sharp_features());
    if (!tags) return;
    const std::size_t n = drag.edges().size();
    set_sharp_features(*tags, std::string(drag.untag() ? "untag " : "tag ") + std::to_string(n) + " crease edge" + (n == 1 ? "" : "s"));
}

}  // namespace app
