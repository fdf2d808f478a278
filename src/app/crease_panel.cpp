#include "app/crease_panel.h"

#include <imgui.h>

#include <string>

#include "app/editor.h"

namespace app {

void crease_panel(Editor& editor) {
    CreaseToolSettings& tool = editor.crease_tool();
    const rgb::SharpFeatures& tags = editor.document().mesh().base().sharp_features();
    ImGui::TextUnformatted("Creases");
    // Every row is there whatever the state, so that nothing below moves under the cursor.
    ImGui::Checkbox("crease tool", &tool.active);
    ImGui::SameLine();
    ImGui::TextDisabled(tool.active ? "drag tags, Shift+drag untags" : "(off: left drag paints)");
    ImGui::SliderFloat("##angle", &tool.sharp_angle_deg, 0.0f, 180.0f, "above %.0f deg");
    ImGui::SameLine();
    if (ImGui::Button("Tag edges"))
        editor.set_sharp_features(with_edges_above(editor.document().mesh(), tool.sharp_angle_deg),
                                  "tag edges above " + std::to_string(static_cast<int>(tool.sharp_angle_deg)) + " degrees");
    ImGui::BeginDisabled(tags.edges.empty() && tags.corners.empty());
    if (ImGui::Button("Clear all tags")) {
        rgb::SharpFeatures cleared;
        cleared.boundary = tags.boundary;
        editor.set_sharp_features(cleared, "clear crease tags");
    }
    ImGui::EndDisabled();
    bool corners = tags.boundary == rgb::BoundaryInterpolation::EdgeAndCorner;
    if (ImGui::Checkbox("boundary corners (edge-and-corner)", &corners)) {
        rgb::SharpFeatures changed = tags;
        changed.boundary = corners ? rgb::BoundaryInterpolation::EdgeAndCorner : rgb::BoundaryInterpolation::EdgeOnly;
        editor.set_sharp_features(changed, std::string("boundary ") + rgb::boundary_interpolation_name(changed.boundary));
    }
    ImGui::Text("%zu sharp edges, %zu corners", tags.edges.size(), tags.corners.size());
}

}  // namespace app
