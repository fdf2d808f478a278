#include "app/lod_panel.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/editor.h"
#include "app/editor_dialogs.h"
#include "app/editor_panels.h"
#include "app/hover_tooltip.h"
#include "app/radio_row.h"

namespace app {
namespace {

// The field shows `text` when it changed outside the panel (a test, the browser); what the user
// types goes back to `text`.
template <std::size_t N>
void text_field(const char* label, std::array<char, N>& field, std::string& text) {
    if (text != field.data()) {
        const std::size_t n = std::min(text.size(), N - 1);
        std::copy_n(text.begin(), n, field.begin());
        field[n] = '\0';
    }
    if (ImGui::InputText(label, field.data(), N)) text = field.data();
}

void levels_table(Editor& editor, const LodLevels& levels) {
    const std::vector<rgbio::LodSetLevel>& set = levels.set.levels;
    if (ImGui::BeginTable("##lods", 4, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
        for (const char* heading : {"level", "triangles", "error", "shown down to"}) ImGui::TableSetupColumn(heading);
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < set.size(); ++i) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text(i > 0 && !set[i].nested ? "LOD%zu*" : "LOD%zu", i);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s%s", set[i].request.text.c_str(), i > 0 && !set[i].nested ? "\n* not nested in the finer level" : "");
            ImGui::TableNextColumn();
            ImGui::Text("%zu", set[i].mesh.num_faces());
            ImGui::TableNextColumn();
            ImGui::Text("%.3g%%", 100.0 * set[i].error / levels.set.size);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%.6g units, against the limit surface (a cage with detail: the dense mesh)", set[i].error);
            ImGui::TableNextColumn();
            ImGui::Text("%.3g", set[i].coverage);
        }
        ImGui::EndTable();
    }
    hover_tooltip("Error: the largest distance of the written level from the surface it stands for, in % of the mesh's size.\n"
                  "Shown down to: the screen coverage (MSFT_screencoverage) below which the next level takes over");
    int shown = editor.previewed_lod() ? static_cast<int>(*editor.previewed_lod()) : -1;
    const std::string format = shown < 0 ? std::string("current mesh") : "LOD%d";
    if (ImGui::SliderInt("preview", &shown, -1, static_cast<int>(set.size()) - 1, format.c_str()))
        editor.preview_lod(shown < 0 ? std::nullopt : std::optional<std::size_t>(shown));
    hover_tooltip("The viewport shows this level as it is written, in place of the mesh; the left end shows the mesh again.\n"
                  "The mesh and its history stay as they are");
}

}  // namespace

void lod_panel(Editor& editor, PanelState& state) {
    LodExportSettings& settings = editor.lod_export_settings();
    settings.criterion = radio_row(
        settings.criterion,
        {{"levels##lods", "Each LOD every face at a subdivision level (as rgbsub lods --levels)"},
         {"budgets##lods", "Each LOD at most so many triangles (as rgbsub lods --budgets)"},
         {"tolerances##lods", "Each LOD within a distance (or % of the size) of the limit surface (as rgbsub lods --tolerances)"}});
    text_field("values##lods", state.lod_values, settings.values);
    hover_tooltip("Comma-separated, in any order: 4,3,1 (levels), 20000,5000 (budgets), 0.1%,1% (tolerances)");
    const bool working = editor.lod_task() != nullptr;
    ImGui::BeginDisabled(working);
    if (ImGui::Button("Make levels")) editor.start_lod_levels();
    ImGui::EndDisabled();
    hover_tooltip("Makes the levels of the mesh as it is, in the background (Esc stops)");
    if (!editor.lod_problem().empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", editor.lod_problem().c_str());
        ImGui::PopTextWrapPos();
    }
    if (working) ImGui::ProgressBar(static_cast<float>(editor.lod_task()->fraction()), ImVec2(-1.0f, 0.0f), "making the levels");
    else if (const LodLevels* levels = editor.lod_levels()) levels_table(editor, *levels);
    else ImGui::TextDisabled("no levels made of the mesh as it is");
    text_field("file##lods", state.lod_path, settings.output);
    hover_tooltip("A .glb or .gltf file holds every level (MSFT_lod); another format writes one file per level,\n"
                  "NAME_LOD0, NAME_LOD1, ... (as rgbsub lods -o)");
    ImGui::SameLine();
    if (ImGui::Button("...##lods")) open_browser(state, FileBrowser::Purpose::ExportLods, state.lod_path[0] != '\0' ? state.lod_path.data() : state.path.data());
    ImGui::BeginDisabled(working);
    if (ImGui::Button("Export")) editor.start_lod_export(settings.output);
    ImGui::EndDisabled();
    hover_tooltip("Makes the levels and writes them to the path above (a failed export writes nothing)");
}

}  // namespace app
