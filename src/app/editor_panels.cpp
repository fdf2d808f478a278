#include "app/editor_panels.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "app/crease_panel.h"
#include "app/detail_panel.h"
#include "app/editor.h"
#include "app/editor_dialogs.h"
#include "app/hover_tooltip.h"
#include "app/radio_row.h"
#include "app/lod_panel.h"
#include "io/script/lod_script.h"
#include "render/colour_map.h"
#include "rgb/mesh/mesh.h"

namespace app {
namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kNoteColour{0.7f, 0.9f, 0.7f, 1.0f};
const ImVec4 kInvertedColour{0.45f, 0.7f, 1.0f, 1.0f};

struct DisplayMode {
    const char* name;
    render::Shading shading;
    render::Colouring colouring;
};
constexpr DisplayMode kDisplayModes[] = {
    {"shaded", render::Shading::Smooth, render::Colouring::Plain},
    {"flat", render::Shading::Flat, render::Colouring::Plain},
    {"matcap (clay)", render::Shading::Smooth, render::Colouring::Matcap},
    {"RGB triangle types", render::Shading::Flat, render::Colouring::RgbType},
    {"level heat map", render::Shading::Smooth, render::Colouring::Level},
    {"material colours", render::Shading::Smooth, render::Colouring::Material},
    {"vertex colours", render::Shading::Smooth, render::Colouring::VertexColour},
    {"texture checker", render::Shading::Smooth, render::Colouring::Checker},
    {"diffuse texture", render::Shading::Smooth, render::Colouring::Texture},
    {"distance to dense mesh", render::Shading::Smooth, render::Colouring::DetailDistance},  // with detail only
};


void copy_path(PanelState& state, const std::string& path) {
    const std::size_t n = std::min(path.size(), state.path.size() - 1);
    std::copy_n(path.begin(), n, state.path.begin());
    state.path[n] = '\0';
}

const char* mode_name(BrushMode mode) {
    switch (mode) {
        case BrushMode::Refine: return "refine";
        case BrushMode::Coarsen: return "coarsen";
        case BrushMode::Set: return "set";
    }
    return "?";
}

void brush_panel(Editor& editor) {
    BrushSettings& brush = editor.brush();
    brush.mode = radio_row(brush.mode, {{"refine", "Adds detail up to the target level (key 1)"},
                                        {"coarsen", "Removes detail down to the target level (key 2)"},
                                        {"set level", "Makes the level exactly the target (key 3)"}});
    brush.target = radio_row(brush.target, {{"level", "Dabs aim for a subdivision level"},
                                            {"detail size",
                                             "Dabs aim for an edge length: no green edge longer (transition diagonals can be),\n"
                                             "as coarse as that allows (no falloff)"},
                                            {"tolerance",
                                             "Dabs aim for accuracy: the surface shown within the amount of the Loop limit surface\n"
                                             "at its samples, as coarse as the criterion allows (no falloff)"}});
    if (brush.target == BrushSettings::Target::Level) {
        ImGui::SliderInt("target level", &brush.target_level, 0, kMaxBrushLevel);
        hover_tooltip("The level painting aims for (keys - and =, or Ctrl+F and drag)");
    } else {
        brush.detail_unit = radio_row(brush.detail_unit,
                                      {{"px##detail", "Relative detail: the amount in screen pixels where the dab lands (zoom in for finer)"},
                                       {"world##detail", "Constant detail: the amount in the mesh's units"}});
        if (brush.detail_unit == RadiusUnit::ScreenPixels)
            ImGui::SliderFloat("amount (px)", &brush.detail_px, 0.1f, 100.0f, "%.3g px", ImGuiSliderFlags_Logarithmic);
        else
            ImGui::DragFloat("amount (world)", &brush.detail_world, brush.detail_world * 0.01f, 1e-6f, 1e6f, "%.4g units");
    }
    brush.unit = radio_row(brush.unit, {{"screen", "Radius in screen pixels: the brush looks the same size at any zoom"},
                                        {"world", "Radius in the mesh's units: the brush covers the same surface at any zoom"}});
    if (brush.unit == RadiusUnit::ScreenPixels)
        ImGui::SliderFloat("radius (px)", &brush.radius_px, 2.0f, 400.0f, "%.0f px");
    else
        ImGui::DragFloat("radius (world)", &brush.radius_world, brush.radius_world * 0.01f, 1e-6f, 1e6f, "%.4g units");
    hover_tooltip("Keys [ and ], or F and drag (a click keeps it, right click or Esc puts it back)");
    ImGui::SliderFloat("spacing", &brush.dabs_per_radius, kLeastDabsPerRadius, kMostDabsPerRadius, "%.1f dabs per radius",
                       ImGuiSliderFlags_Logarithmic);
    hover_tooltip("How close the dabs lie along a stroke: more dabs per radius paint a smoother edge, fewer paint faster");
    ImGui::SliderFloat("lazy mouse", &brush.lazy_px, 0.0f, kMostLazyPx, brush.lazy_px > 0.0f ? "%.0f px string" : "off");
    hover_tooltip("The brush trails the pointer on a string this long and moves only when the pointer pulls it:\n"
                  "hand jitter shorter than the string leaves a smooth stroke (the string shows while painting)");
    ImGui::SliderFloat("falloff", &brush.falloff, 0.0f, 1.0f, "%.2f of radius");
    hover_tooltip("The part of the radius, from the rim in, over which the level tapers off");
    ImGui::Checkbox("paint through", &brush.paint_through);
    hover_tooltip("Off: only faces facing you and connected to the point under the cursor change.\n"
            "On: everything within the radius, the far side of thin parts too.");
    unsigned int mirror = brush.mirror;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("mirror");
    for (const auto& [label, plane] : {std::pair{"X##mirror", rgbio::kMirrorX}, std::pair{"Y##mirror", rgbio::kMirrorY},
                                       std::pair{"Z##mirror", rgbio::kMirrorZ}}) {
        ImGui::SameLine();
        ImGui::CheckboxFlags(label, &mirror, plane);
    }
    brush.mirror = static_cast<std::uint8_t>(mirror);
    hover_tooltip("Symmetry: each dab also paints its mirror images across the planes x = 0, y = 0, z = 0 of the mesh's\n"
                  "own frame (the file's coordinates), one request, saved as one 'dab ... mirror' script line");
    // What a drag does now: Shift visibly turns refining into removing detail.
    const BrushMode active = editor.active_mode();
    const std::string action = std::string(mode_name(active)) +
                               (brush.target == BrushSettings::Target::Level        ? " to level " + std::to_string(editor.active_level())
                                : brush.target == BrushSettings::Target::DetailSize ? std::string(" to the detail size")
                                                                                    : std::string(" to the tolerance"));
    if (active != brush.mode) ImGui::TextColored(kInvertedColour, "Shift held: drag will %s", action.c_str());
    else ImGui::TextDisabled("drag: %s (Shift: inverse)", action.c_str());
}

void actions_panel(Editor& editor, PanelState& state) {
    ImGui::SliderInt("##flood", &state.flood_level, 0, kMaxBrushLevel, "level %d");
    ImGui::SameLine();
    if (ImGui::Button("Set all")) editor.start_flood_fill(state.flood_level);
    hover_tooltip("Every face to this level, coarse to fine over the next frames (Esc stops)");
    if (ImGui::Button("Sample level under cursor (S)")) editor.sample_level_under_cursor();
    AutoLodSettings& lod = editor.auto_lod_settings();
    // On a cage with detail the budget goes where the surface departs most from the dense mesh.
    const bool detail = editor.document().mesh().base().detail() != nullptr;
    int budget = static_cast<int>(lod.triangle_budget);
    ImGui::DragInt("triangle budget", &budget, 1000.0f, 100, 20000000);
    hover_tooltip(detail ? "Automatic LOD refines where the surface departs most from the dense mesh until the mesh has this many triangles"
                         : "Automatic LOD refines the longest edges until the mesh has this many triangles");
    lod.triangle_budget = static_cast<std::size_t>(std::max(budget, 100));
    if (detail) {
        float distance = static_cast<float>(lod.max_distance_fraction * 100.0);
        ImGui::SliderFloat("max distance", &distance, 0.0001f, 1.0f, "%.4f %% of size", ImGuiSliderFlags_Logarithmic);
        hover_tooltip("Where the surface departs from the dense mesh by more than this share of the mesh's size, it gets refined,\n"
                      "the farthest first (the distance heat map in Display shows the same measure)");
        lod.max_distance_fraction = distance / 100.0;
    } else {
        float edge = static_cast<float>(lod.max_edge_fraction * 100.0);
        ImGui::SliderFloat("max edge", &edge, 0.05f, 10.0f, "%.2f %% of size", ImGuiSliderFlags_Logarithmic);
        hover_tooltip("Edges longer than this share of the mesh's size get refined");
        lod.max_edge_fraction = edge / 100.0;
    }
    if (ImGui::Button("Automatic LOD")) editor.start_auto_lod();
    const UndoHistory& history = editor.document().history();
    const std::string undo = history.can_undo() ? "Undo " + history.undo_label() : std::string("Undo");
    const std::string redo = history.can_redo() ? "Redo " + history.redo_label() : std::string("Redo");
    // Half the row each, named by a fixed id: Redo stays put when Undo's label changes.
    const ImVec2 half((ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2.0f, 0.0f);
    if (ImGui::Button((undo + "###undo").c_str(), half)) editor.undo();
    hover_tooltip("Ctrl+Z");
    ImGui::SameLine();
    if (ImGui::Button((redo + "###redo").c_str(), half)) editor.redo();
    hover_tooltip("Ctrl+Shift+Z or Ctrl+Y");
    ImGui::Text("%zu/%zu steps, history %.1f of %.0f MB", history.undo_steps(), history.undo_steps() + history.redo_steps(),
                static_cast<double>(history.bytes()) / 1e6, static_cast<double>(history.byte_bound()) / 1e6);
}

// The path field follows the document (the File section shows it; the browser starts there), and
// goes back to it after a file that could not be opened. A made document without a file (a cage)
// or a sample shows the name Save proposes.
void follow_document_path(Editor& editor, PanelState& state) {
    const std::string& shown = editor.suggested_path().empty() ? editor.document().path() : editor.suggested_path();
    if (shown != state.shown_document_path || editor.open_failures() != state.seen_open_failures) {
        state.shown_document_path = shown;
        state.seen_open_failures = editor.open_failures();
        copy_path(state, state.shown_document_path);
    }
}

void files_panel(Editor& editor, PanelState& state) {
    ImGui::InputText("path", state.path.data(), state.path.size());
    hover_tooltip("The file Open and Save as use; ... browses");
    ImGui::SameLine();
    if (ImGui::Button("...")) open_browser(state, FileBrowser::Purpose::Open, state.path.data());
    if (ImGui::Button("Open")) editor.request_open(state.path.data());
    hover_tooltip("Ctrl+O browses");
    ImGui::SameLine();
    if (ImGui::Button("Save")) editor.request_save();
    hover_tooltip("Ctrl+S, to the document's file");
    ImGui::SameLine();
    if (ImGui::Button("Save as")) editor.request_save_as(state.path.data());
    hover_tooltip("To the path above; Ctrl+Shift+S browses");
    ImGui::SameLine();
    if (ImGui::Button("Save strokes")) open_browser(state, FileBrowser::Purpose::SaveStrokes, state.path.data());
    hover_tooltip("Ctrl+E: the edits in effect as a script; rgbsub apply FILE.obj SCRIPT -o OUT.obj replays them");
    int positions = static_cast<int>(editor.save_options().positions);
    ImGui::RadioButton("displayed positions", &positions, 0);
    ImGui::SameLine();
    ImGui::RadioButton("limit", &positions, 1);
    hover_tooltip("Which positions a save writes: as shown, or on the Loop limit surface");
    editor.save_options().positions = static_cast<rgbio::SavedPositions>(positions);
    bool msh_binary = editor.save_options().msh == rgbio::MshEncoding::Binary;
    ImGui::Checkbox("binary .msh", &msh_binary);
    hover_tooltip("Save as and Export LODs to a .msh name write Gmsh 4.1 binary (raw doubles, smaller, no decimals to\n"
                  "parse) instead of ASCII, as rgbsub's --msh-binary");
    editor.save_options().msh = msh_binary ? rgbio::MshEncoding::Binary : rgbio::MshEncoding::Ascii;
    // The UV and recent rows are there (greyed) without UVs or recent files too, so that the rows
    // below do not move when a file is opened.
    const std::optional<rgb::UvInterpolation> uv = editor.document().uv_interpolation();
    ImGui::BeginDisabled(!uv);
    constexpr const char* kUvOptions[] = {"none", "corners", "boundaries", "all"};
    if (ImGui::BeginCombo("UV interpolation", uv ? kUvOptions[static_cast<int>(*uv)] : "no texture coordinates")) {
        for (int option = 0; option < 4; ++option)
            if (ImGui::Selectable(kUvOptions[option], uv && option == static_cast<int>(*uv)))
                editor.document().set_uv_interpolation(static_cast<rgb::UvInterpolation>(option));
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    hover_tooltip("How texture coordinates are subdivided, shown and saved (OpenSubdiv's FVAR_LINEAR_* options): none moves\n"
                  "every UV but those a sharp feature pins (seams become smooth curves), corners keeps UV corners in place,\n"
                  "boundaries keeps seams and borders on their input lines, all is linear over each base triangle");
    ImGui::BeginDisabled(editor.recent_files().empty());
    if (ImGui::BeginCombo("recent", editor.recent_files().empty() ? "no recent files" : "choose a recent file")) {
        for (const std::string& recent : editor.recent_files())
            if (ImGui::Selectable(recent.c_str())) copy_path(state, recent);
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
}

// `detail`: the mesh is a cage with detail, which the distance heat map needs.
void display_panel(Editor& editor, render::RenderOptions& options, bool detail) {
    const auto offered = [detail](const DisplayMode& mode) { return detail || mode.colouring != render::Colouring::DetailDistance; };
    // A mode not offered (the distance heat map after opening a mesh without detail) falls back to the first.
    const DisplayMode* current = &kDisplayModes[0];
    for (const DisplayMode& mode : kDisplayModes)
        if (offered(mode) && mode.shading == options.shading && mode.colouring == options.colouring) current = &mode;
    if (ImGui::BeginCombo("mode", current->name)) {
        for (const DisplayMode& mode : kDisplayModes)
            if (offered(mode) && ImGui::Selectable(mode.name, &mode == current)) current = &mode;
        ImGui::EndCombo();
    }
    hover_tooltip("Matcap lights the surface like clay under studio lights fixed to the view, which shows its shape and\n"
            "small detail clearly. The heat map gives every level one colour of its own. Material colours (Kd), vertex colours, the checker\n"
            "over the texture coordinates and the diffuse texture show the file's data: the exact colours and texture\n"
            "coordinates at the positions' level, the values a saved OBJ of this mesh holds. On a cage with detail, the\n"
            "distance to the dense mesh colours each triangle by its largest departure from it, in fixed bands of the\n"
            "mesh's size (the legend gives them in % and in units)");
    options.shading = current->shading;
    options.colouring = current->colouring;
    ImGui::Checkbox("wireframe", &options.wireframe);
    hover_tooltip("Lines fade where triangles are only a few pixels across");
    ImGui::SameLine();
    ImGui::Checkbox("base mesh", &options.base_mesh_overlay);
    hover_tooltip("The input's control cage over the surface");
    bool limit = options.positions == render::PositionSource::Limit;
    ImGui::Checkbox("limit positions", &limit);
    hover_tooltip("Show (and pick on) the Loop limit surface instead of the mesh's own positions");
    options.positions = limit ? render::PositionSource::Limit : render::PositionSource::Displayed;
    bool orthographic = editor.camera().camera().orthographic;
    if (ImGui::Checkbox("orthographic", &orthographic)) editor.camera().set_orthographic(orthographic);
    hover_tooltip("Numpad 5. Numpad 1, 3, 7: front, right, top view (Ctrl: back, left, bottom)");
    ImGui::TextDisabled("back faces (through holes): brick-red");
}

// The colour and level counts are the displayed triangles' (kept as the display follows the mesh,
// so they cost nothing per frame at any size).
void statistics_panel(Editor& editor, PanelState& state) {
    const rgb::Mesh& mesh = editor.document().mesh();
    const render::SurfaceGeometry& geometry = editor.document().shown();
    ImGui::Text("V %zu   F %zu", mesh.num_vertices(), mesh.num_faces());
    ImGui::Text("green %zu  red %zu  blue %zu", geometry.triangles_of(rgb::Colour::Green),
                geometry.triangles_of(rgb::Colour::Red), geometry.triangles_of(rgb::Colour::Blue));
    for (int level = 0; level <= geometry.max_face_level(); ++level) {
        const std::size_t count = geometry.triangles_at(level);
        if (count == 0) continue;
        const glm::vec3 c = render::level_colour(level);
        ImGui::TextColored(ImVec4(c.r, c.g, c.b, 1.0f), "level %2d", level);
        ImGui::SameLine();
        ImGui::Text("%zu triangles", count);
    }
    const EngineTiming& timing = editor.timing();
    ImGui::Text("engine %.2f ms last frame (%zu operations)", timing.frame_ms, timing.frame_operations);
    ImGui::Text("pick %.3f ms, stroke start %.3f ms", timing.last_pick_ms, timing.stroke_start_ms);
    ImGui::Text("frame %.1f ms (without waiting for input)", state.frame_ms);
}

void shortcuts_panel() {
    ImGui::TextUnformatted(
        "left drag        paint (Shift: inverse)\n"
        "right drag       orbit (or Alt+left)\n"
        "middle drag      pan (or Alt+Shift+left)\n"
        "wheel            zoom to the cursor\n"
        "Home / R         frame mesh / reset view\n"
        "[ / ]            smaller / larger brush\n"
        "F, drag, click   brush radius\n"
        "- / =            target level down / up\n"
        "Ctrl+F, drag     brush target (level, amount)\n"
        "1 2 3            refine / coarsen / set level\n"
        "S                sample level under cursor\n"
        "numpad 1 3 7     front / right / top view\n"
        "                 (Ctrl: back / left / bottom)\n"
        "numpad 5         orthographic / perspective\n"
        "Ctrl+Z           undo\n"
        "Ctrl+Shift+Z, Ctrl+Y  redo\n"
        "Ctrl+O           open (file browser)\n"
        "Ctrl+S           save\n"
        "Ctrl+Shift+S     save as (file browser)\n"
        "Ctrl+E           save the strokes as a script\n"
        "Ctrl+Q           quit\n"
        "Esc              stop the work under way\n"
        "drop an OBJ on the window to open it");
}

// One line at the bottom: the last message (whole in a tooltip) and the progress of what runs.
void status_bar(Editor& editor) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.0f, display.y - kStatusBarHeight), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(display.x, kStatusBarHeight), ImGuiCond_Always);
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
    constexpr float kProgressWidth = 320.0f;
    std::string work;
    float fraction = -1.0f;
    if (const BackgroundTask* task = editor.file_task() ? editor.file_task() : editor.lod_task()) {
        work = task->status();
        fraction = static_cast<float>(task->fraction());
    } else if (const MeshJob* job = editor.job()) {
        fraction = job->progress();
        work = job->label() + (editor.jobs_waiting() > 0 ? " (+" + std::to_string(editor.jobs_waiting()) + " waiting)" : "") + ", Esc stops";
    }
    const float message_width = display.x - (fraction >= 0.0f ? kProgressWidth + 16.0f : 8.0f);
    ImGui::PushClipRect(ImGui::GetCursorScreenPos(), ImVec2(ImGui::GetCursorScreenPos().x + message_width, display.y), true);
    ImGui::TextColored(editor.message_is_error() ? kErrorColour : kNoteColour, "%s", editor.message().c_str());
    ImGui::PopClipRect();
    if (ImGui::IsItemHovered() && !editor.message().empty()) ImGui::SetTooltip("%s", editor.message().c_str());
    if (fraction >= 0.0f) {
        ImGui::SameLine(display.x - kProgressWidth - 8.0f);
        ImGui::ProgressBar(fraction, ImVec2(kProgressWidth, 0.0f), work.c_str());
    }
    ImGui::End();
}

// A section's header, open as the layout remembers it (or by default), and the layout told what it
// is now (a click toggles it).
bool section(PanelLayout& layout, const char* label, bool open_by_default) {
    const auto remembered = layout.sections.find(label);
    ImGui::SetNextItemOpen(remembered != layout.sections.end() ? remembered->second : open_by_default, ImGuiCond_Once);
    const bool open = ImGui::CollapsingHeader(label);
    layout.sections[label] = open;
    return open;
}

}  // namespace

void draw_panels(Editor& editor, PanelState& state, render::RenderOptions& options) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Anchored to the right edge at every size, above the status bar; framing keeps the mesh clear of it.
    ImGui::SetNextWindowPos(ImVec2(display.x - kPanelWidth - 8.0f, 8.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, std::max(display.y - 16.0f - kStatusBarHeight, 100.0f)), ImGuiCond_Always);
    ImGui::SetNextWindowCollapsed(!state.layout.panel_open, ImGuiCond_Once);
    state.layout.panel_open = ImGui::Begin("rgbsub", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    editor.set_covered_right(state.layout.panel_open ? kPanelCover : 0.0f);
    follow_document_path(editor, state);
    if (state.layout.panel_open) {
        PanelLayout& layout = state.layout;
        ImGui::PushItemWidth(-120.0f);
        if (section(layout, "Brush", true)) brush_panel(editor);
        crease_panel(editor);
        if (section(layout, "Whole mesh", true)) actions_panel(editor, state);
        if (section(layout, "Detail by size, accuracy, view", true)) detail_panel(editor);
        if (section(layout, "File", true)) files_panel(editor, state);
        // Below File and folded at first, so that File's controls stay where they were.
        if (section(layout, "Export LODs", false)) lod_panel(editor, state);
        if (section(layout, "Display", true)) display_panel(editor, options, editor.document().mesh().base().detail() != nullptr);
        if (section(layout, "Statistics", false)) statistics_panel(editor, state);
        if (section(layout, "Shortcuts", false)) shortcuts_panel();
        ImGui::PopItemWidth();
    }
    ImGui::End();
    status_bar(editor);
    switch (editor.take_browse_request()) {
        case Editor::Browse::Open: open_browser(state, FileBrowser::Purpose::Open, state.path.data()); break;
        case Editor::Browse::SaveAs: open_browser(state, FileBrowser::Purpose::SaveAs, state.path.data()); break;
        case Editor::Browse::SaveStrokes: open_browser(state, FileBrowser::Purpose::SaveStrokes, state.path.data()); break;
        case Editor::Browse::None: break;
    }
    file_browser(editor, state.browser);
    questions(editor);
}

}  // namespace app
