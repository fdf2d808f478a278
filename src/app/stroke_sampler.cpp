#include "app/stroke_sampler.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace app {

std::vector<glm::vec2> StrokeSampler::begin(glm::vec2 press) {
    last_dab_ = press;
    return {press};
}

std::vector<glm::vec2> StrokeSampler::move_to(glm::vec2 sample, float spacing) {
    spacing = std::max(spacing, 1.0f);
    std::vector<glm::vec2> dabs;
    float remaining = glm::distance(last_dab_, sample);
    if (remaining < spacing) return dabs;
    const glm::vec2 step = (sample - last_dab_) / remaining * spacing;
    for (; remaining >= spacing; remaining -= spacing) {
        last_dab_ += step;
        dabs.push_back(last_dab_);
    }
    return dabs;
}

}  // namespace app
