#include "app/ui_input_queue.h"

namespace app {

void UiInputQueue::deliver(ImGuiIO& io) {
    std::array<bool, kButtons> button_changed{};
    std::array<bool, kKeySlots> key_changed{};
    bool any_button_changed = false, moved = false, wheeled = false;
    ImVec2 wheel(0.0f, 0.0f);
    while (!events_.empty()) {
        const Event& event = events_.front();
        if (event.kind == Kind::Move) {
            // Where a press happened stays its frame's position: a move after it waits.
            if (any_button_changed || wheeled) break;
            position_ = event.value;
            moved = true;
        } else if (event.kind == Kind::Button) {
            if (event.code < 0 || event.code >= kButtons) {
                events_.pop_front();
                continue;
            }
            if (button_changed[event.code] || wheeled) break;
            button_changed[event.code] = any_button_changed = true;
            buttons_[event.code] = event.down;
        } else if (event.kind == Kind::Key) {
            if (event.code < 0 || event.code >= kKeySlots) {
                events_.pop_front();
                continue;
            }
            if (key_changed[event.code] || any_button_changed) break;
            key_changed[event.code] = true;
            keys_[event.code] = event.down;
        } else {
            if (moved || any_button_changed) break;
            wheel.x += event.value.x;
            wheel.y += event.value.y;
            wheeled = true;
        }
        events_.pop_front();
    }
    io.MousePos = position_;
    for (int b = 0; b < kButtons; ++b) io.MouseDown[b] = buttons_[b];
    for (int k = 0; k < kKeySlots; ++k) io.KeysDown[k] = keys_[k];
    const auto held = [this](const std::array<int, 2>& slots) { return keys_[slots[0]] || keys_[slots[1]]; };
    io.KeyCtrl = held(modifiers_.ctrl);
    io.KeyShift = held(modifiers_.shift);
    io.KeyAlt = held(modifiers_.alt);
    io.KeySuper = held(modifiers_.super);
    io.MouseWheelH = wheel.x;
    io.MouseWheel = wheel.y;
}

}  // namespace app
