#pragma once
// The editor's modal dialogs (Dear ImGui): the questions it must ask before discarding work, and a
// file browser for opening and saving. Called between ImGui::NewFrame and ImGui::Render.
#include "app/editor_panels.h"

namespace app {

class Editor;

// Opens the browser in the folder of `current` (or the working folder) with its name filled in.
void open_browser(PanelState& state, FileBrowser::Purpose purpose, const char* current);
void file_browser(Editor& editor, FileBrowser& browser);
void questions(Editor& editor);

}  // namespace app
