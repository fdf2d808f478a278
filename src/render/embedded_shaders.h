#pragma once
// GLSL sources from shaders/, compiled into the binary (see embed_shaders.cmake).
#include <span>
#include <string_view>

namespace render {

struct EmbeddedShader {
    std::string_view name;  // file name in shaders/, used in error messages
    std::string_view source;
};

std::span<const EmbeddedShader> embedded_shaders();
// The shader called `name`; throws std::out_of_range naming it if there is none.
const EmbeddedShader& embedded_shader(std::string_view name);

}  // namespace render
