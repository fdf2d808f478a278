#pragma once
// A row of radio buttons that chooses one value of an enum, each button with its tooltip: the panels'
// brush mode and target, brush and detail units, and Export LODs' criterion.
#include <initializer_list>

#include <imgui.h>

#include "app/hover_tooltip.h"

namespace app {

struct RadioChoice {
    const char* label;    // ImGui label, unique in its window (a ##suffix where the text repeats)
    const char* tooltip;  // shown while the mouse rests on the button
};

// The buttons on one line, the i-th choosing the enum's value i; returns `current`, or the value of
// the button clicked this frame.
template <class Enum>
Enum radio_row(Enum current, std::initializer_list<RadioChoice> choices) {
    int chosen = static_cast<int>(current);
    int value = 0;
    for (const RadioChoice& choice : choices) {
        if (value > 0) ImGui::SameLine();
        ImGui::RadioButton(choice.label, &chosen, value++);
        hover_tooltip(choice.tooltip);
    }
    return static_cast<Enum>(chosen);
}

}  // namespace app
