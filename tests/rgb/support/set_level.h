// A Set request in one call, as tests write it: every face meeting the ball (the whole surface
// without one) gets `level`. Only tests asked for it, so it is not in the core, whose callers build
// a LevelRequest.
#pragma once

#include <optional>

#include "rgb/lod/requests.h"

namespace rgbtest {

inline rgb::RequestStats set_level(rgb::Mesh& mesh, int level, std::optional<rgb::Sphere> sphere = std::nullopt) {
    rgb::LevelRequest request;
    request.level = level;
    request.sphere = sphere;
    return rgb::apply_request(mesh, request);
}

}  // namespace rgbtest
