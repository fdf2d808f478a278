#pragma once
// An editor in an 800x600 viewport, scripted through the same input calls the window makes.
#include <string>

#include <gtest/gtest.h>

#include <glm/vec2.hpp>

#include "app/editor.h"
#include "test_paths.h"

namespace app::test {

inline constexpr glm::ivec2 kViewport{800, 600};

class EditorFixture : public ::testing::Test {
protected:

    // A left-drag from `from` to `to` in `samples` mouse events, as a fast mouse delivers them, and
    // the stroke's work run to its end (the window spreads it over frames).
    void stroke(glm::vec2 from, glm::vec2 to, int samples, Modifiers mods = {}) {
        editor.mouse_moved(from);
        editor.mouse_pressed(MouseButton::Left, mods);
        for (int i = 1; i <= samples; ++i) editor.mouse_moved(from + (to - from) * (float(i) / float(samples)));
        editor.mouse_released(MouseButton::Left);
        editor.finish_work();
    }

    // A drag with `button` by `delta` pixels from `start`.
    void drag(MouseButton button, glm::vec2 start, glm::vec2 delta, Modifiers mods = {}) {
        editor.mouse_moved(start);
        editor.mouse_pressed(button, mods);
        editor.mouse_moved(start + delta);
        editor.mouse_released(button);
    }

    Editor editor{kViewport};
};

}  // namespace app::test
