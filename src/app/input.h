#pragma once
// The editor's own input vocabulary, independent of GLFW, so that tests can script the editor
// without a window (editor_window.cpp maps GLFW's codes onto these).
namespace app {

enum class MouseButton { Left, Right, Middle };

enum class Key { F, R, Z, Y, S, O, Q, E, LeftBracket, RightBracket, Minus, Equal, Digit1, Digit2, Digit3, Digit4, Digit5, Escape,
                 Keypad1, Keypad3, Keypad5, Keypad7, Home };

struct Modifiers {
    bool shift = false;
    bool ctrl = false;
    bool alt = false;
};

}  // namespace app
