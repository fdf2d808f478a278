#include "app/stroke_script.h"

namespace app {

std::string StrokeScript::lines(const rgb::Dab& dab, std::uint8_t mirror) {
    const rgbio::BrushEdit brush{dab.mode, dab.level, dab.radius, dab.falloff};
    std::string out;
    if (!brush_ || brush_->mode != brush.mode || brush_->level != brush.level || brush_->radius != brush.radius ||
        brush_->falloff != brush.falloff) {
        out = rgbio::format_brush_line(brush) + "\n";
        brush_ = brush;
    }
    return out + rgbio::format_dab_line(rgbio::DabEdit{dab.centre, dab.view, mirror}) + "\n";
}

}  // namespace app
