#pragma once
// F and Ctrl+F, as in Blender's sculpt mode: the brush's radius, or its target, set by dragging. The
// adjustment draws a circle around a centre placed so that the pointer's distance from it shows the
// current value; moving the pointer changes the value, a left click keeps it, a right click or Esc
// puts the old one back. GL-free (the view draws the circle and the value).
#include <string>

#include <glm/vec2.hpp>

#include "app/brush.h"

namespace app {

// Ctrl+F with the level target: this many pixels from the centre per level.
inline constexpr float kPixelsPerLevel = 24.0f;
// A radius in world units or a detail amount: the pointer starts this far from the centre, and the
// value scales with the distance (twice as far: twice the value).
inline constexpr float kScaleDistance = 100.0f;

struct BrushAdjust {
    enum class What { Radius, Target } what = What::Radius;
    glm::vec2 centre{0.0f};  // screen pixels
    float start_distance = 0.0f;
    BrushSettings before;  // what a cancel puts back
};

BrushAdjust begin_brush_adjust(const BrushSettings& brush, BrushAdjust::What what, glm::vec2 pointer);
// The pointer at `pointer`: the value its distance from the centre means, into `brush`.
void adjust_brush(const BrushAdjust& adjust, glm::vec2 pointer, BrushSettings& brush);
// What the view shows beside the circle: "radius 53 px", "target level 5", ...
std::string brush_adjust_label(const BrushAdjust& adjust, const BrushSettings& brush);

}  // namespace app
