#pragma once
// Spreads dabs evenly along a stroke, so that a fast mouse (few samples far apart) leaves no gaps:
// between two samples it emits a dab every `spacing` pixels, carrying the remainder over.
#include <vector>

#include <glm/vec2.hpp>

namespace app {

class StrokeSampler {
public:
    // The first dab sits on the press position.
    std::vector<glm::vec2> begin(glm::vec2 press);
    // Dabs on the segment from the last dab towards `sample`; none if it moved less than `spacing`.
    std::vector<glm::vec2> move_to(glm::vec2 sample, float spacing);

private:
    glm::vec2 last_dab_{0.0f};
};

}  // namespace app
