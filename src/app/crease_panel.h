#pragma once
// The editor's Creases panel (Dear ImGui): the crease tool's switch, tagging by angle, clearing, the
// boundary option and the counts. Called by draw_panels (editor_panels.h).
namespace app {

class Editor;

void crease_panel(Editor& editor);

}  // namespace app
