#pragma once
// The panels explain each control in a tooltip shown while the mouse rests on it.
#include <imgui.h>

namespace app {

// Shows `text` as a tooltip if the mouse is over the item drawn last.
inline void hover_tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace app
