#include "app/detail_panel.h"

#include <imgui.h>

#include <array>
#include <charconv>

#include "app/editor.h"
#include "app/hover_tooltip.h"
#include "app/radio_row.h"

namespace app {
namespace {

// The double a person typed or dragged to in a float field: its shortest decimal form (0.1, not
// 0.10000000149011612), which the job's label, the status line and the script line then print.
double as_shown(float value) {
    std::array<char, 32> text{};
    const auto written = std::to_chars(text.data(), text.data() + text.size(), value);
    double exact = value;
    std::from_chars(text.data(), written.ptr, exact);
    return exact;
}

}  // namespace

void detail_panel(Editor& editor) {
    DetailSettings& detail = editor.detail_settings();
    detail.criterion = radio_row(detail.criterion,
                                 {{"max edge",
                                   "No green edge longer than the amount (as `rgbsub refine --max-edge`; transition diagonals can be),\n"
                                   "as coarse as that allows"},
                                  {"tolerance",
                                   "The surface shown within the amount of the Loop limit surface at its samples\n"
                                   "(as `rgbsub refine --tolerance`), as coarse as the criterion allows"}});
    float amount = static_cast<float>(detail.amount.value);
    // Taken only when changed: the float would otherwise replace the exact default every frame.
    if (ImGui::DragFloat("amount", &amount, amount * 0.01f, 1e-6f, 1e6f, "%.4g", ImGuiSliderFlags_Logarithmic) && amount > 0.0f)
        detail.amount.value = as_shown(amount);
    ImGui::SameLine();
    ImGui::Checkbox("%", &detail.amount.percent);
    hover_tooltip("On: a percentage of the mesh's bounding-box diagonal; off: the mesh's units");
    if (ImGui::Button("Apply to the whole mesh")) editor.start_detail_edit();
    hover_tooltip("Over the next frames; Esc stops; one undo step");

    float pixels = static_cast<float>(detail.view_pixels);
    ImGui::SliderFloat("view detail", &pixels, 1.0f, 64.0f, "%.1f px", ImGuiSliderFlags_Logarithmic);
    hover_tooltip("View-dependent LOD: edges longer than this on screen are split, shorter than half of it\n"
            "removed; outside the view and on the back only what visible detail needs stays");
    ViewLodJob* running = editor.view_lod();
    if (static_cast<double>(pixels) != detail.view_pixels) {
        detail.view_pixels = pixels;
        if (running) {
            rgb::ViewLodSettings settings = running->settings();
            settings.pixels = pixels;
            running->set_settings(settings);
        }
    }
    if (!running) {
        if (ImGui::Button("View-dependent LOD")) editor.start_view_lod();
        hover_tooltip("Detail follows the camera every frame until you freeze it");
        return;
    }
    if (ImGui::Button("Freeze")) editor.freeze_view_lod();
    hover_tooltip("Esc: keeps the mesh as it is, an ordinary editable state (one undo step)");
    ImGui::SameLine();
    ImGui::TextUnformatted(running->converged() ? "settled for this view" : "following the camera");
}

}  // namespace app
