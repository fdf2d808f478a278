#include "app/brush_adjust.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace app {
namespace {

float& scaled_value(BrushSettings& brush, BrushAdjust::What what) {
    if (what == BrushAdjust::What::Radius) return brush.unit == RadiusUnit::ScreenPixels ? brush.radius_px : brush.radius_world;
    return brush.detail_unit == RadiusUnit::ScreenPixels ? brush.detail_px : brush.detail_world;
}

// How far from the centre the pointer shows the brush's value now.
float distance_for(const BrushSettings& brush, BrushAdjust::What what) {
    if (what == BrushAdjust::What::Radius) return brush.unit == RadiusUnit::ScreenPixels ? brush.radius_px : kScaleDistance;
    if (brush.target == BrushSettings::Target::Level) return static_cast<float>(brush.target_level) * kPixelsPerLevel;
    return kScaleDistance;
}

std::string adjust_text(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

}  // namespace

BrushAdjust begin_brush_adjust(const BrushSettings& brush, BrushAdjust::What what, glm::vec2 pointer) {
    BrushAdjust adjust;
    adjust.what = what;
    adjust.start_distance = distance_for(brush, what);
    adjust.centre = pointer - glm::vec2(adjust.start_distance, 0.0f);
    adjust.before = brush;
    return adjust;
}

void adjust_brush(const BrushAdjust& adjust, glm::vec2 pointer, BrushSettings& brush) {
    const float distance = glm::distance(pointer, adjust.centre);
    if (adjust.what == BrushAdjust::What::Target && brush.target == BrushSettings::Target::Level) {
        brush.target_level = std::clamp(static_cast<int>(std::lround(distance / kPixelsPerLevel)), 0, kMaxBrushLevel);
        return;
    }
    if (adjust.what == BrushAdjust::What::Radius && brush.unit == RadiusUnit::ScreenPixels) {
        brush.radius_px = std::clamp(distance, kLeastRadiusPx, kMostRadiusPx);
        return;
    }
    BrushSettings before = adjust.before;
    const float from = scaled_value(before, adjust.what);
    const bool pixels = adjust.what == BrushAdjust::What::Target && brush.detail_unit == RadiusUnit::ScreenPixels;
    scaled_value(brush, adjust.what) =
        std::clamp(from * std::max(distance, 1.0f) / adjust.start_distance, pixels ? 0.1f : 1e-6f, pixels ? 100.0f : 1e6f);
}

std::string brush_adjust_label(const BrushAdjust& adjust, const BrushSettings& brush) {
    if (adjust.what == BrushAdjust::What::Radius)
        return brush.unit == RadiusUnit::ScreenPixels ? adjust_text("radius %.0f px", brush.radius_px) : adjust_text("radius %.4g units", brush.radius_world);
    switch (brush.target) {
        case BrushSettings::Target::Level: return "target level " + std::to_string(brush.target_level);
        case BrushSettings::Target::DetailSize:
        case BrushSettings::Target::Tolerance: {
            const std::string name = brush.target == BrushSettings::Target::DetailSize ? "detail size " : "tolerance ";
            return name + (brush.detail_unit == RadiusUnit::ScreenPixels ? adjust_text("%.3g px", brush.detail_px)
                                                                         : adjust_text("%.4g units", brush.detail_world));
        }
    }
    return {};
}

}  // namespace app
