#pragma once
// The editor's Dear ImGui panels: a side panel (brush, whole mesh, file, display, statistics,
// shortcuts) anchored to the right edge, a one-line status bar at the bottom, the modal questions
// and a file browser. Plain functions of the editor state (no GL, no window), called between
// ImGui::NewFrame and ImGui::Render.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "app/editor_settings.h"
#include "render/renderer.h"

namespace app {

class Editor;

// The status bar's height in pixels (the side panel's width is kPanelWidth, editor.h).
inline constexpr float kStatusBarHeight = 26.0f;

// The file browser: a folder listing to pick a file from, and a name to type.
struct FileBrowser {
    enum class Purpose { None, Open, SaveAs, SaveStrokes, ExportLods };
    Purpose purpose = Purpose::None;
    std::filesystem::path folder;
    std::array<char, 256> name{};
};

// What the panels remember between frames.
struct PanelState {
    std::array<char, 1024> path{};
    std::string shown_document_path;  // the document path the field last showed
    std::uint64_t seen_open_failures = 0;
    int flood_level = 2;
    double frame_ms = 0.0;  // the window's own work in the last frame, not the wait for input
    FileBrowser browser;
    std::array<char, 256> lod_values{};  // the Export LODs fields (lod_panel.h)
    std::array<char, 1024> lod_path{};
    PanelLayout layout;  // kept between sessions (editor_settings.h)
};

// Draws every panel and applies what the user did to `editor` and `options`.
void draw_panels(Editor& editor, PanelState& state, render::RenderOptions& options);

}  // namespace app
