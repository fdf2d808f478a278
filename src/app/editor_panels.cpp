#include "app/editor_panels.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <vector>

#include "app/crease_panel.h"
#include "app/editor.h"
#include "rgb/mesh.h"

namespace app {
namespace {

constexpr float kPanelWidth = 300.0f;
constexpr double kHistogramRefreshS = 0.25;

struct DisplayMode {
    const char* name;
    render::Shading shading;
    render::Colouring colouring;
};
constexpr DisplayMode kDisplayModes[] = {
    {"shaded", render::Shading::Smooth, render::Colouring::Plain},
    {"flat", render::Shading::Flat, render::Colouring::Plain},
    {"RGB triangle types", render::Shading::Flat, render::Colouring::RgbType},
    {"level heat map", render::Shading::Smooth, render::Colouring::Level},
};

void copy_path(PanelState& state, const std::string& path) {
    const std::size_t n = std::min(path.size(), state.path.size() - 1);
    std::copy_n(path.begin(), n, state.path.begin());
    state.path[n] = '\0';
}

void brush_panel(Editor& editor) {
    BrushSettings& brush = editor.brush();
    ImGui::TextUnformatted("Brush (left drag paints)");
    int mode = static_cast<int>(brush.mode);
    ImGui::RadioButton("refine", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("coarsen", &mode, 1);
    ImGui::SameLine();
    ImGui::RadioButton("set level", &mode, 2);
    brush.mode = static_cast<BrushMode>(mode);
    ImGui::SliderInt("target level", &brush.target_level, 0, kMaxBrushLevel);
    int unit = static_cast<int>(brush.unit);
    ImGui::RadioButton("screen", &unit, 0);
    ImGui::SameLine();
    ImGui::RadioButton("world", &unit, 1);
    brush.unit = static_cast<RadiusUnit>(unit);
    if (brush.unit == RadiusUnit::ScreenPixels)
        ImGui::SliderFloat("radius (px)", &brush.radius_px, 2.0f, 400.0f, "%.0f px");
    else
        ImGui::DragFloat("radius (world)", &brush.radius_world, brush.radius_world * 0.01f, 1e-6f, 1e6f, "%.4g units");
    ImGui::SliderFloat("falloff", &brush.falloff, 0.0f, 1.0f, "%.2f of radius");
    if (editor.active_mode() != brush.mode) ImGui::TextColored({1.0f, 0.7f, 0.2f, 1.0f}, "Shift: inverted");
}

void actions_panel(Editor& editor, PanelState& state) {
    ImGui::TextUnformatted("Whole mesh");
    ImGui::SliderInt("##flood", &state.flood_level, 0, kMaxBrushLevel, "level %d");
    ImGui::SameLine();
    if (ImGui::Button("Set all")) editor.start_flood_fill(state.flood_level);
    if (ImGui::Button("Sample level under cursor (S)")) editor.sample_level_under_cursor();
    AutoLodSettings& lod = editor.auto_lod_settings();
    int budget = static_cast<int>(lod.triangle_budget);
    ImGui::DragInt("triangle budget", &budget, 1000.0f, 100, 20000000);
    lod.triangle_budget = static_cast<std::size_t>(std::max(budget, 100));
    float edge = static_cast<float>(lod.max_edge_fraction * 100.0);
    ImGui::SliderFloat("max edge", &edge, 0.05f, 10.0f, "%.2f %% of size", ImGuiSliderFlags_Logarithmic);
    lod.max_edge_fraction = edge / 100.0;
    if (ImGui::Button("Automatic LOD")) editor.start_auto_lod();
    if (const MeshJob* job = editor.job()) {
        ImGui::ProgressBar(job->progress(), ImVec2(-70.0f, 0.0f), job->label().c_str());
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) editor.cancel_job();
    }
    const UndoHistory& history = editor.document().history();
    if (ImGui::Button("Undo")) editor.undo();
    ImGui::SameLine();
    if (ImGui::Button("Redo")) editor.redo();
    ImGui::SameLine();
    ImGui::Text("%zu/%zu steps", history.undo_steps(), history.undo_steps() + history.redo_steps());
    ImGui::Text("history %.1f of %.0f MB", static_cast<double>(history.bytes()) / 1e6,
                static_cast<double>(history.byte_bound()) / 1e6);
}

void files_panel(Editor& editor, PanelState& state) {
    ImGui::TextUnformatted("File");
    ImGui::InputText("path", state.path.data(), state.path.size());
    if (ImGui::Button("Open")) editor.request_open(state.path.data());
    ImGui::SameLine();
    if (ImGui::Button("Save")) editor.save();
    ImGui::SameLine();
    if (ImGui::Button("Save as")) editor.request_save_as(state.path.data());
    int positions = static_cast<int>(editor.save_options().positions);
    ImGui::RadioButton("displayed positions", &positions, 0);
    ImGui::SameLine();
    ImGui::RadioButton("limit", &positions, 1);
    editor.save_options().positions = static_cast<rgbio::SavedPositions>(positions);
    if (!editor.recent_files().empty() && ImGui::BeginCombo("recent", "choose a recent file")) {
        for (const std::string& recent : editor.recent_files())
            if (ImGui::Selectable(recent.c_str())) copy_path(state, recent);
        ImGui::EndCombo();
    }
    if (!editor.message().empty()) {
        const ImVec4 colour = editor.message_is_error() ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.7f, 0.9f, 0.7f, 1.0f);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(colour, "%s", editor.message().c_str());
        ImGui::PopTextWrapPos();
    }
}

void display_panel(render::RenderOptions& options) {
    ImGui::TextUnformatted("Display");
    const DisplayMode* current = &kDisplayModes[0];
    for (const DisplayMode& mode : kDisplayModes)
        if (mode.shading == options.shading && mode.colouring == options.colouring) current = &mode;
    if (ImGui::BeginCombo("mode", current->name)) {
        for (const DisplayMode& mode : kDisplayModes)
            if (ImGui::Selectable(mode.name, &mode == current)) current = &mode;
        ImGui::EndCombo();
    }
    options.shading = current->shading;
    options.colouring = current->colouring;
    ImGui::Checkbox("wireframe", &options.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("base mesh", &options.base_mesh_overlay);
    bool limit = options.positions == render::PositionSource::Limit;
    ImGui::Checkbox("limit positions", &limit);
    options.positions = limit ? render::PositionSource::Limit : render::PositionSource::Displayed;
}

void statistics_panel(Editor& editor, PanelState& state, double dt_s) {
    const rgb::Mesh& mesh = editor.document().mesh();
    state.histogram_age_s += dt_s;
    if (state.histogram_age_s >= kHistogramRefreshS) {
        state.faces_per_level.clear();
        for (rgb::FaceId f : mesh.faces()) ++state.faces_per_level[mesh.level(f)];
        state.histogram_age_s = 0.0;
    }
    const render::SurfaceGeometry& geometry = editor.document().geometry();
    ImGui::TextUnformatted("Statistics");
    ImGui::Text("V %zu   F %zu", mesh.num_vertices(), mesh.num_faces());
    ImGui::Text("green %zu  red %zu  blue %zu", geometry.triangles_of(rgb::Colour::Green),
                geometry.triangles_of(rgb::Colour::Red), geometry.triangles_of(rgb::Colour::Blue));
    std::vector<float> bars(kMaxBrushLevel + 1, 0.0f);  // a fixed axis, levels 0..max
    std::string levels;
    for (const auto& [level, count] : state.faces_per_level) {
        bars.resize(std::max(bars.size(), static_cast<std::size_t>(level) + 1), 0.0f);
        bars[static_cast<std::size_t>(level)] = static_cast<float>(count);
        if (!levels.empty()) levels += ' ';
        levels += std::to_string(level);
        levels += ':';
        levels += std::to_string(count);
    }
    ImGui::PlotHistogram("##levels", bars.data(), static_cast<int>(bars.size()), 0, "triangles per level", 0.0f,
                         FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, 50.0f));
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(levels.c_str());
    ImGui::PopTextWrapPos();
    const DabTiming& dab = editor.dab_timing();
    ImGui::Text("last dab: engine %.2f ms, pick %.2f ms", dab.last_ms, dab.last_pick_ms);
    ImGui::Text("          %zu splits and removals", dab.last_operations);
    ImGui::Text("frame %.1f ms", state.frame_ms);
}

void shortcuts_panel() {
    if (!ImGui::CollapsingHeader("Shortcuts")) return;
    ImGui::TextUnformatted(
        "left drag        paint (Shift: invert)\n"
        "right drag       orbit (or Alt+left)\n"
        "middle drag      pan (or Alt+Shift+left)\n"
        "wheel            zoom\n"
        "F / R            frame mesh / reset view\n"
        "[ / ]            smaller / larger brush\n"
        "1 2 3            refine / coarsen / set level\n"
        "S                sample level under cursor\n"
        "Ctrl+Z           undo\n"
        "Ctrl+Shift+Z, Ctrl+Y  redo\n"
        "Ctrl+S           save\n"
        "Ctrl+Q           quit\n"
        "Esc              cancel running job\n"
        "drop an OBJ on the window to open it");
}

void questions(Editor& editor) {
    const char* title = nullptr;
    std::string text;
    switch (editor.pending()) {
        case Pending::None: return;
        case Pending::DiscardForQuit: title = "Quit?"; text = "Discard unsaved changes and quit?"; break;
        case Pending::DiscardForOpen:
            title = "Open?";
            text = "Discard unsaved changes and open " + editor.pending_path() + "?";
            break;
        case Pending::Overwrite: title = "Overwrite?"; text = editor.pending_path() + " exists. Replace it?"; break;
    }
    ImGui::OpenPopup(title);
    if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(text.c_str());
        if (ImGui::Button("Yes")) editor.answer_pending(true);
        ImGui::SameLine();
        if (ImGui::Button("No")) editor.answer_pending(false);
        ImGui::EndPopup();
    }
}

}  // namespace

void draw_panels(Editor& editor, PanelState& state, render::RenderOptions& options, double dt_s) {
    state.frame_ms = 0.9 * state.frame_ms + 0.1 * dt_s * 1000.0;
    if (state.path[0] == '\0' && !editor.document().path().empty()) copy_path(state, editor.document().path());
    // On the right: the renderer's level legend sits in the bottom-left corner.
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - kPanelWidth - 8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("rgbsub");
    ImGui::PushItemWidth(-110.0f);
    brush_panel(editor);
    ImGui::Separator();
    crease_panel(editor);
    ImGui::Separator();
    actions_panel(editor, state);
    ImGui::Separator();
    files_panel(editor, state);
    ImGui::Separator();
    display_panel(options);
    ImGui::Separator();
    statistics_panel(editor, state, dt_s);
    ImGui::Separator();
    shortcuts_panel();
    ImGui::PopItemWidth();
    ImGui::End();
    questions(editor);
}

}  // namespace app
