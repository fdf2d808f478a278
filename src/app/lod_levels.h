#pragma once
// The editor's Export LODs: what the user asks for (the criterion and its values, where to write),
// and the levels made of the document for the preview, each with the display the viewport shows in
// place of the mesh. The levels are io/lod_set_files.h's, the same `rgbsub lods` writes.
#include <cstdint>
#include <string>
#include <vector>

#include "io/lod_set_files.h"
#include "io/script/lod_set.h"
#include "render/surface_geometry.h"

namespace app {

struct LodExportSettings {
    rgbio::LodSetCriterion criterion = rgbio::LodSetCriterion::Levels;
    std::string values = "3,2,1,0";  // as `rgbsub lods` takes them: `4,3,1`, `20000,5000`, `0.1%,1%`
    std::string output;              // the path Export writes to (the last one exported)
};

struct LodLevels {
    rgbio::LodSet set;
    // One per level, finest first, at the positions the level is written with.
    std::vector<render::SurfaceGeometry> displays;
    // Document::changes() when the levels were made of it: they are stale once it differs.
    std::uint64_t changes = 0;
};

// The position source that shows a level as it is written.
inline render::PositionSource written_source(rgbio::SavedPositions positions) {
    return positions == rgbio::SavedPositions::Limit ? render::PositionSource::Limit : render::PositionSource::Displayed;
}

}  // namespace app
