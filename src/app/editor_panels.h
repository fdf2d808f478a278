#pragma once
// The editor's Dear ImGui panels: brush, mesh actions, files, display, statistics, shortcuts, and
// the modal questions. Plain functions of the editor state (no GL, no window), called between
// ImGui::NewFrame and ImGui::Render.
#include <array>
#include <cstddef>
#include <map>

#include "render/renderer.h"

namespace app {

class Editor;

// What the panels remember between frames.
struct PanelState {
    std::array<char, 1024> path{};
    int flood_level = 2;
    double frame_ms = 0.0;
    // Level histogram, refreshed now and then (it costs a pass over the faces).
    std::map<int, std::size_t> faces_per_level;
    double histogram_age_s = 1e9;
};

// Draws every panel and applies what the user did to `editor` and `options`.
void draw_panels(Editor& editor, PanelState& state, render::RenderOptions& options, double dt_s);

}  // namespace app
