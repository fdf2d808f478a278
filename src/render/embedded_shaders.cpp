#include "render/embedded_shaders.h"

#include <stdexcept>
#include <string>

namespace render {

const EmbeddedShader& embedded_shader(std::string_view name) {
    for (const EmbeddedShader& shader : embedded_shaders())
        if (shader.name == name) return shader;
    throw std::out_of_range("no embedded shader named '" + std::string(name) + "'");
}

}  // namespace render
