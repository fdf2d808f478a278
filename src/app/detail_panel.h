#pragma once
// The editor's Detail panel (Dear ImGui): max edge or tolerance over the whole mesh, and the
// view-dependent mode with its pixel threshold and freeze. Called by draw_panels (editor_panels.h).
namespace app {

class Editor;

void detail_panel(Editor& editor);

}  // namespace app
