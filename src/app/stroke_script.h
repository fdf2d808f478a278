#pragma once
// A stroke's dabs as lines of a level-of-detail script (io/script/lod_script.h): a `brush` line whenever the
// dab's base-space radius or settings differ from the previous dab's (always before the first), then
// `dab X Y Z [VX VY VZ] [mirror AXES]`. Numbers are written so that they read back exactly, so `rgbsub apply`
// makes the same requests the editor made.
#include <cstdint>
#include <optional>
#include <string>

#include "io/script/lod_script.h"
#include "rgb/lod/dab.h"

namespace app {

class StrokeScript {
public:
    // The lines of a dab and its mirror images (rgbio::with_mirror_images): one `dab ... mirror` line.
    std::string lines(const rgb::Dab& dab, std::uint8_t mirror);

private:
    std::optional<rgbio::BrushEdit> brush_;
};

}  // namespace app
