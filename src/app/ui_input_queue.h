#pragma once
// The window's mouse and key events for ImGui, queued as they come and handed over a frame at a
// time. Debian 12's ImGui (1.86, the one we build with) reads the input as a state at each frame's
// start, so a press and its release between two frames (a quick click, a key tapped while frames are
// slow) left no trace, and a click landed where the pointer was at the frame's start rather than
// where it was pressed. Here each frame takes the events in order up to the first that would undo a
// change it already took (the rule of ImGui's own event queue from 1.87 on; ours until Debian's
// ImGui has it): the press goes in one frame, the release in the next, each at the position it
// happened at. The window draws frames until the queue is empty.
#include <array>
#include <cfloat>
#include <deque>

#include <imgui.h>

namespace app {

class UiInputQueue {
public:
    // ImGui's key slots (io.KeysDown) of the modifier keys, left and right, for io.KeyCtrl and the rest.
    struct ModifierSlots {
        std::array<int, 2> ctrl, shift, alt, super;
    };
    explicit UiInputQueue(const ModifierSlots& modifiers) : modifiers_(modifiers) {}

    void mouse_moved(ImVec2 position) { events_.push_back({Kind::Move, 0, false, position}); }
    // The pointer left the window: ImGui hovers nothing.
    void mouse_left() { mouse_moved(ImVec2(-FLT_MAX, -FLT_MAX)); }
    void mouse_button(int button, bool down) { events_.push_back({Kind::Button, button, down, {}}); }
    void key(int slot, bool down) { events_.push_back({Kind::Key, slot, down, {}}); }
    void scrolled(ImVec2 wheel) { events_.push_back({Kind::Wheel, 0, false, wheel}); }

    // Takes this frame's share of the events into `io` (after the platform backend's NewFrame, which
    // would otherwise set the mouse from its own state, and before ImGui::NewFrame).
    void deliver(ImGuiIO& io);
    bool empty() const { return events_.empty(); }

private:
    enum class Kind { Move, Button, Key, Wheel };
    struct Event {
        Kind kind;
        int code;  // the button or the key slot
        bool down;
        ImVec2 value;  // the position, or the wheel's steps
    };
    static constexpr int kButtons = 5;
    static constexpr int kKeySlots = 512;

    ModifierSlots modifiers_;
    std::deque<Event> events_;
    ImVec2 position_{-FLT_MAX, -FLT_MAX};
    std::array<bool, kButtons> buttons_{};
    std::array<bool, kKeySlots> keys_{};
};

}  // namespace app
