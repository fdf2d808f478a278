#pragma once
// The editor's Export LODs panel (Dear ImGui): the criterion and its values as `rgbsub lods` takes
// them, the levels made with their triangles, error and switch coverage, a slider that previews each
// in the viewport, and the export to a path. Called by draw_panels (editor_panels.h).
namespace app {

class Editor;
struct PanelState;

void lod_panel(Editor& editor, PanelState& state);

}  // namespace app
